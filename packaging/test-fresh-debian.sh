#!/usr/bin/env bash
# Runs the README's two commands on a fresh Debian 12, as a new user would:
# a new `debootstrap --variant=minbase bookworm` chroot, a clean clone of this
# repository's HEAD (committed work only) with ../shared beside it (read-only),
# then ./scripts/start.sh and ./scripts/test.sh, each timed. Nothing of this
# machine's packages or build reaches the chroot, so a package missing from
# scripts/setup.sh fails here. Run it whenever a dependency changes.
#
#   sudo packaging/test-fresh-debian.sh [--suite bookworm|trixie] [--reuse] [CHROOT]
#
# --suite: Debian 12 (bookworm, the default) or Debian 13 (trixie, issue #49).
# CHROOT (default /var/tmp/lpv-fresh-SUITE) is deleted and made anew unless
# --reuse is given (then its packages and build stay: a second-run check).
# Logs: CHROOT.logs/{start,test,artefacts}.log; the rendered PNG: CHROOT.logs/cornell-box.png;
# then, for comparing releases, CHROOT.logs/cornell.{exr,png} (a 256x256 render),
# cornell-reference.exr (1024 spp of the same view) and the .deb from cpack.
# Exits non-zero when either command fails; prints both times either way.
set -euo pipefail

reuse=0
SUITE=bookworm
while [ $# -gt 0 ]; do
  case $1 in
    --reuse) reuse=1; shift ;;
    --suite) SUITE=${2:?--suite needs bookworm or trixie}; shift 2 ;;
    *) break ;;
  esac
done
case $SUITE in bookworm | trixie) ;; *) echo "--suite: bookworm or trixie, not $SUITE" >&2; exit 2 ;; esac
ROOT=${1:-/var/tmp/lpv-fresh-$SUITE}
REPO=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
SHARED=$(realpath "$REPO/../shared")
LOGS="$ROOT.logs"
[ -d "$SHARED/scenes" ] || { echo "no ../shared/scenes beside $REPO" >&2; exit 2; }

source "$(dirname "$0")/chroot-common.sh"
if [ "$reuse" -eq 0 ] && [ -e "$ROOT" ]; then
  echo "== removing the old chroot $ROOT"
  for m in $(awk -v r="$ROOT/" 'index($2, r) == 1 {print $2}' /proc/mounts | sort -r); do umount -l "$m"; done
  rm -rf --one-file-system "$ROOT"
fi
start=$SECONDS
chroot_bootstrap
echo "== chroot ready in $((SECONDS - start)) s: $(chroot "$ROOT" dpkg-query -W | wc -l) packages"
chroot_mount
chroot_bind "$SHARED" /work/shared ro

if [ ! -d "$ROOT/work/lpvstudio/.git" ]; then
  git clone -q --no-local "$REPO" "$ROOT/work/lpvstudio"
else
  git -C "$ROOT/work/lpvstudio" fetch -q "$REPO" HEAD && git -C "$ROOT/work/lpvstudio" reset -q --hard FETCH_HEAD
fi
echo "== clean clone of $(git -C "$ROOT/work/lpvstudio" log -1 --format='%h %s')"

mkdir -p "$LOGS"
# Runs one README command in the clone; its output goes to the log and, from
# the scripts' own "== " lines and the last lines, to the terminal.
declare -A seconds status
readme_command() { # NAME
  local t0=$SECONDS rc=0
  echo "== ./scripts/$1.sh (log: $LOGS/$1.log)"
  in_chroot bash -c "cd /work/lpvstudio && ./scripts/$1.sh" >"$LOGS/$1.log" 2>&1 || rc=$?
  seconds[$1]=$((SECONDS - t0))
  status[$1]=$rc
  grep -E '^== ' "$LOGS/$1.log" || true
  tail -n 5 "$LOGS/$1.log"
  echo "== ./scripts/$1.sh: exit $rc after ${seconds[$1]} s"
}
readme_command start
cp "$ROOT/work/lpvstudio/out/cornell-box.png" "$LOGS/" 2>/dev/null || true
readme_command test

# What one release's build makes, for comparing the two (issue #49): a render
# of the Cornell template (EXR and PNG) and a path-traced reference of the
# same view, and the .deb (cpack) for test-deb-in-chroot.sh.
echo "== the Cornell template's render and reference, and the package (log: $LOGS/artefacts.log)"
t0=$SECONDS
status[artefacts]=0
in_chroot bash -c 'cd /work/lpvstudio && lpv=build/app/cli/lpv p=projects/cornell-box/cornell-box.lpvproj &&
  $lpv render $p -o /tmp/cornell.exr --width 256 --height 256 &&
  $lpv render $p -o /tmp/cornell.png --width 256 --height 256 &&
  $lpv reference $p -o /tmp/cornell-reference.exr --width 256 --height 256 --spp 1024 &&
  cd build && rm -f lpvstudio_*.deb && cpack -G DEB' >"$LOGS/artefacts.log" 2>&1 || status[artefacts]=$?
for f in cornell.exr cornell.png cornell-reference.exr; do cp "$ROOT/tmp/$f" "$LOGS/" 2>/dev/null || true; done
cp "$ROOT"/work/lpvstudio/build/lpvstudio_*.deb "$LOGS/" 2>/dev/null || true
tail -n 3 "$LOGS/artefacts.log"
echo "== artefacts: exit ${status[artefacts]} after $((SECONDS - t0)) s: $(cd "$LOGS" && ls cornell* ./*.deb 2>/dev/null | tr '\n' ' ')"

echo "== summary (fresh $SUITE chroot, $(nproc) cores)"
for c in start test; do echo "./scripts/$c.sh: exit ${status[$c]}, ${seconds[$c]} s"; done
echo "artefacts (render, reference, .deb): exit ${status[artefacts]}"
[ "${status[start]}" -eq 0 ] && [ "${status[test]}" -eq 0 ] && [ "${status[artefacts]}" -eq 0 ]
