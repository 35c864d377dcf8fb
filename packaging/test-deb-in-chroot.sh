#!/usr/bin/env bash
# Installs a built lpvstudio .deb into a fresh Debian 12 (bookworm) or 13
# (trixie; a package built on that release, issue #49) and checks
# that both programs work there, as on a user's new machine: apt resolves the
# package's dependencies from the Debian archive, `lpv render` renders the
# installed Cornell box, and `lpvstudio` starts and renders under Xvfb.
#
#   sudo packaging/test-deb-in-chroot.sh [--suite bookworm|trixie] build/lpvstudio_0.1.0_amd64.deb [CHROOT]
#
# CHROOT (default /var/tmp/lpv-deb-SUITE) is made with `debootstrap --variant=minbase`
# when missing and reused otherwise (the package is purged first). Needs root,
# debootstrap and a Debian mirror: DEBIAN_MIRROR, else the one this machine's
# apt uses. Prints every command it runs; exits non-zero on the first failure.
set -euo pipefail

SUITE=bookworm
if [ "${1:-}" = "--suite" ]; then
  SUITE=${2:?--suite needs bookworm or trixie}
  shift 2
fi
case $SUITE in bookworm | trixie) ;; *) echo "--suite: bookworm or trixie, not $SUITE" >&2; exit 2 ;; esac
DEB=$(realpath "$1")
ROOT=${2:-/var/tmp/lpv-deb-$SUITE}

source "$(dirname "$0")/chroot-common.sh"
chroot_bootstrap
chroot_mount

cp "$DEB" "$ROOT/tmp/"
in_chroot apt-get update -qq
in_chroot apt-get purge -y -qq lpvstudio >/dev/null 2>&1 || true
# Without Recommends: the package's Depends alone must be enough to run both programs.
in_chroot apt-get install -y -qq --no-install-recommends "/tmp/$(basename "$DEB")" >/dev/null
in_chroot sh -c 'echo "$(dpkg -l | grep -c ^ii) packages installed"'
in_chroot dpkg -s lpvstudio | grep -E '^(Status|Version|Depends):'

echo "== the command-line tool"
in_chroot lpv --version
in_chroot rm -f /tmp/x.png
in_chroot lpv render /usr/share/lpvstudio/projects/cornell-box/cornell-box.lpvproj -o /tmp/x.png
in_chroot test -s /tmp/x.png
in_chroot ls -l /tmp/x.png
cp "$ROOT/tmp/x.png" "${LPV_CHROOT_RENDER_COPY:-/tmp/lpv-deb-$SUITE-cornell-box.png}"

echo "== the editor (Xvfb: the package does not bring an X server, a desktop has one)"
in_chroot apt-get install -y -qq --no-install-recommends xvfb xauth >/dev/null
in_chroot timeout 120 xvfb-run -a -s "-screen 0 1280x1024x24" lpvstudio --quit-after 5000
# Started without arguments, it stays up until it is closed (here: killed by timeout, exit 124).
set +e
in_chroot timeout 10 xvfb-run -a -s "-screen 0 1280x1024x24" lpvstudio
rc=$?
set -e
echo "exit code $rc (124: still running when timeout stopped it)"
[ "$rc" -eq 124 ]

echo "== desktop integration (caches refreshed by dpkg triggers, where the tools are installed)"
if [ -f "$ROOT/usr/share/mime/globs2" ]; then
  in_chroot grep -F 'application/x-lpvproj:*.lpvproj' /usr/share/mime/globs2
else
  echo "shared-mime-info is not installed in the chroot: no MIME database to check"
fi
echo "== all checks passed"
