#!/usr/bin/env bash
# Proves scripts/setup.sh's package list complete for the build in BUILD_DIR:
# every system file the build read (the headers in the compiler's dependency
# files, the libraries on the link lines) must belong to a Debian package that
# setup.sh installs, or that one of those pulls in through Depends/Pre-Depends,
# or that a minbase Debian has (Priority: required). Fails naming each missing
# package, with one file of it and how many the build used.
#
#   tests/install/check-install-list.sh BUILD_DIR [--without PACKAGE]...
#
# --without drops a package from the list (the suite uses it to show that the
# check fails when a needed package is left out). Needs dpkg, apt-cache, ninja
# and a finished build (ninja records the headers only of what it compiled).
set -euo pipefail

build=$(realpath "$1")
shift
without=()
while [ $# -gt 0 ]; do
  case $1 in
    --without) without+=("$2"); shift 2 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
source_dir=$(realpath "$(dirname "$0")/../..")
[ -f "$build/build.ninja" ] || { echo "no build.ninja in $build: build first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. The roots: setup.sh's list (less --without) and what minbase installs.
"$source_dir/scripts/setup.sh" --print-packages >"$work/listed"
for p in "${without[@]}"; do
  grep -vxF "$p" "$work/listed" >"$work/listed.new" || true
  mv "$work/listed.new" "$work/listed"
done
dpkg-query -W -f='${Package} ${Priority}\n' | awk '$2 == "required" {print $1}' >"$work/required"
dpkg-query -W -f='${Package} ${db:Status-Abbrev}\n' | awk '$2 ~ /^ii/ {print $1}' >"$work/installed"

# 2. Their closure as apt would install it on a machine that has none of them:
# the first alternative of each "a | b" group, the installed (else the first)
# provider of a virtual package. Recommends are not followed (setup.sh
# installs with --no-install-recommends).
mapfile -t roots < <(sort -u "$work/listed" "$work/required")
apt-cache depends --no-recommends --no-suggests --no-conflicts --no-breaks --no-replaces --no-enhances \
  --recurse "${roots[@]}" >"$work/depends" 2>/dev/null
awk -v rootsFile="$work/listed" -v requiredFile="$work/required" -v installedFile="$work/installed" '
  function bare(n) { gsub(/[<>]/, "", n); sub(/:.*/, "", n); return n }
  # A dependency alternative ends when the next one starts or the stanza ends.
  function closeAlt() {
    if (alt != "") { groups[pkg, g, ++nalts[pkg, g]] = alt "=" provs }
    alt = ""; provs = ""
  }
  BEGIN {
    while ((getline l < installedFile) > 0) installed[l] = 1
  }
  /^[^ ]/ { closeAlt(); pkg = bare($1); g = ngroups[pkg]; inOr = 0; next }
  /^ [ |](Pre)?Depends: / {
    closeAlt()
    if (!inOr) { g = ++ngroups[pkg] }
    inOr = ($0 ~ /^ \|/)
    alt = ($2 ~ /^</) ? "<" bare($2) : bare($2)
    next
  }
  /^    / { provs = provs (provs == "" ? "" : " ") bare($1); next }
  /^  / { closeAlt(); next }
  END {
    closeAlt()
    n = 0
    while ((getline l < rootsFile) > 0) queue[++n] = l
    while ((getline l < requiredFile) > 0) queue[++n] = l
    for (i = 1; i <= n; i++) {
      p = queue[i]
      if (p in seen) continue
      seen[p] = 1
      print p
      for (gi = 1; gi <= ngroups[p]; gi++) {
        chosen = ""
        for (ai = 1; ai <= nalts[p, gi] && chosen == ""; ai++) {
          split(groups[p, gi, ai], parts, "=")
          name = parts[1]; np = split(parts[2], providers, " ")
          if (name !~ /^</) { chosen = name; break }
          for (k = 1; k <= np; k++) if (providers[k] in installed) { chosen = providers[k]; break }
          if (chosen == "" && np > 0) chosen = providers[1]
        }
        if (chosen != "") queue[++n] = chosen
      }
    }
  }' "$work/depends" | sort -u >"$work/closure"

# 3. The system files the build read: headers from ninja's dependency log,
# libraries from the link lines (absolute paths and -l names).
ninja -C "$build" -t deps | awk '/^    \// {print $1}' >"$work/files.raw"
{
  grep -h -E '^ *LINK_LIBRARIES = ' "$build/build.ninja" || true
} | tr ' ' '\n' | sort -u >"$work/link-tokens"
grep -E '^/.*\.(so(\.[0-9]+)*|a)$' "$work/link-tokens" >>"$work/files.raw" || true
compiler=$(awk -F= '/^CMAKE_CXX_COMPILER:/ {print $2}' "$build/CMakeCache.txt")
for lib in $(sed -n 's/^-l//p' "$work/link-tokens") stdc++ gcc_s c m; do
  for f in "lib$lib.so" "lib$lib.a"; do
    found=$("$compiler" -print-file-name="$f")
    if [ "$found" != "$f" ]; then echo "$found" >>"$work/files.raw"; break; fi
  done
done
# Our own files are not the system's.
grep -v -e "^$source_dir/" -e "^$build/" "$work/files.raw" | xargs -d "\n" realpath -s |
  sort -u >"$work/files"

# 4. Which package owns each file. dpkg knows the path it installed, which on a
# merged-/usr system may be the /lib spelling of a /usr/lib file; a path no
# package names (an alternatives link) is looked up by its target.
spellings() {
  case $1 in
    /usr/lib/* | /usr/bin/* | /usr/sbin/*) echo "$1"; echo "${1#/usr}" ;;
    /lib/* | /lib64/* | /bin/* | /sbin/*) echo "$1"; echo "/usr$1" ;;
    *) echo "$1" ;;
  esac
}
# realpath resolves every file's links in one process.
xargs -d '\n' realpath -m <"$work/files" | paste "$work/files" - >"$work/pairs"
while IFS=$'\t' read -r f r; do
  spellings "$f"
  [ "$r" = "$f" ] || spellings "$r"
done <"$work/pairs" | sort -u >"$work/lookups"
xargs -d '\n' dpkg-query -S <"$work/lookups" 2>/dev/null | grep -v '^diversion by' >"$work/owners" || true

awk -v closureFile="$work/closure" -v ownersFile="$work/owners" -v pairsFile="$work/pairs" '
  function canon(p) { sub(/^\/usr\//, "/", p); return p }
  BEGIN {
    while ((getline l < closureFile) > 0) inClosure[l] = 1
    while ((getline l < ownersFile) > 0) {
      i = index(l, ": "); path = substr(l, i + 2); pkgs = substr(l, 1, i - 1)
      owners[canon(path)] = pkgs
    }
    bad = 0; checked = 0
    while ((getline l < pairsFile) > 0) {
      checked++
      split(l, pair, "\t"); f = pair[1]; target = pair[2]
      o = (canon(f) in owners) ? owners[canon(f)] : (target != "" && canon(target) in owners) ? owners[canon(target)] : ""
      if (o == "") { unowned[f] = 1; bad++; continue }
      n = split(o, list, ", "); ok = 0
      for (k = 1; k <= n; k++) { sub(/:.*/, "", list[k]); if (list[k] in inClosure) ok = 1 }
      if (!ok) {
        if (!(list[1] in missing)) example[list[1]] = f
        missing[list[1]]++; bad++
      }
    }
    for (p in missing)
      printf "MISSING PACKAGE %s: the build reads %d of its files (e.g. %s), but scripts/setup.sh neither installs it nor pulls it in\n", p, missing[p], example[p]
    for (f in unowned) printf "NOT FROM A DEBIAN PACKAGE: %s\n", f
    printf "%d system files checked against %d packages (setup.sh list and its closure)\n", checked, length(inClosure)
    exit bad > 0
  }'
