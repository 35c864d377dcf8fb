# Sourced by the chroot tests (test-deb-in-chroot.sh, test-fresh-debian.sh):
# makes or reuses a minbase Debian chroot (SUITE: bookworm, Debian 12, unless
# the caller sets trixie, Debian 13), mounts what programs need in it, and
# runs commands there in a clean environment. Needs root and debootstrap.
#
#   ROOT=...; [SUITE=trixie;] source packaging/chroot-common.sh
#   chroot_bootstrap            debootstrap --variant=minbase "$SUITE" "$ROOT" when missing
#   chroot_mount                proc, sys (with its cgroup mounts), dev, dev/pts, dev/shm (unmounted on exit)
#   chroot_bind SRC DEST [ro]   bind-mount a host folder into the chroot (unmounted on exit)
#   in_chroot CMD...            run CMD in the chroot, printing it first

# The mirror this machine already uses, so the scripts name none themselves.
mirrorFor() { # $1: archive path, "debian" or "debian-security"
  { grep -rhoE "^(URIs:|deb) +https?://[^ ]+/$1/?( |\$)" /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null ||
    true; } | awk '{print $2}' | head -n 1
}
SUITE=${SUITE:-bookworm}
MIRROR=${DEBIAN_MIRROR:-$(mirrorFor debian)}
SECURITY=${DEBIAN_SECURITY_MIRROR:-$(mirrorFor debian-security)}
[ -n "$MIRROR" ] || { echo "no Debian mirror found: set DEBIAN_MIRROR" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "debootstrap is not installed (apt-get install debootstrap)" >&2; exit 2; }

chroot_bootstrap() {
  if [ ! -x "$ROOT/usr/bin/apt-get" ]; then
    echo "== debootstrap --variant=minbase $SUITE $ROOT"
    debootstrap --variant=minbase "$SUITE" "$ROOT" "$MIRROR" >/dev/null
  fi
  # An installed Debian follows the point-release updates and security fixes.
  {
    echo "deb $MIRROR $SUITE main"
    echo "deb $MIRROR $SUITE-updates main"
    [ -z "$SECURITY" ] || echo "deb $SECURITY $SUITE-security main"
  } >"$ROOT/etc/apt/sources.list"
  # The chroot reaches the archive the way this machine does: its resolver and
  # its apt proxy and validity-date settings (a snapshot mirror), in a file of
  # our own name, so that no package's conffile is pre-empted (apt would ask).
  cp -L /etc/resolv.conf "$ROOT/etc/resolv.conf" 2>/dev/null || true
  grep -hE '^ *Acquire::((https?|ftp)::Proxy|Check-Valid-Until|Check-Date)' -r /etc/apt/apt.conf /etc/apt/apt.conf.d/ \
    2>/dev/null >"$ROOT/etc/apt/apt.conf.d/99lpv-host-acquire" || true
}

chroot_mounted=()
chroot_cleanup() {
  for ((i = ${#chroot_mounted[@]} - 1; i >= 0; i--)); do umount -l "${chroot_mounted[i]}" || true; done
}
trap chroot_cleanup EXIT

chroot_mount() {
  for m in proc sys dev dev/pts dev/shm; do
    mountpoint -q "$ROOT/$m" && continue
    case $m in
      proc) mount -t proc proc "$ROOT/proc" ;;
      # Recursive, so /sys/fs/cgroup comes along as on a booted machine (the
      # cluster test's slurmd needs it); rslave: unmounting here changes nothing outside.
      sys) mount --rbind /sys "$ROOT/sys" && mount --make-rslave "$ROOT/sys" ;;
      dev/shm) mkdir -p "$ROOT/dev/shm" && mount -t tmpfs shm "$ROOT/dev/shm" ;;
      *) mount --bind "/$m" "$ROOT/$m" ;;
    esac
    chroot_mounted+=("$ROOT/$m")
  done
}

chroot_bind() { # SRC DEST-in-chroot [ro]
  mkdir -p "$ROOT$2"
  mountpoint -q "$ROOT$2" && return 0
  mount --bind "$1" "$ROOT$2"
  [ "${3:-}" != ro ] || mount -o remount,bind,ro "$ROOT$2"
  chroot_mounted+=("$ROOT$2")
}

# A clean environment: nothing of this machine's (DISPLAY, LD_LIBRARY_PATH...) leaks in.
in_chroot() {
  echo "+ $*"
  chroot "$ROOT" env -i PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive "$@"
}
