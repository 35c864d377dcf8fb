#!/usr/bin/env bash
# Runs the thesis application (djbozkosz/Light-Propagation-Volumes, GPL-3.0,
# an external program: nothing of it is in this repository) headless under
# Xvfb with Mesa llvmpipe and prints its own per-phase timer as medians, so
# it can be alternated with `lpv bench render --thesis-settings` (issue #25).
# The checkout must be built with the Linux patch described in README.md
# (its THESIS_BENCH_* hooks).
#
#   tools/thesis-app/run.sh CHECKOUT [FRAMES] [options]
#
#   CHECKOUT           the built thesis checkout (bin/LightPropagationVolumes.exe, data/)
#   FRAMES             measured frames per run (default 10)
#   --warmup N         frames rendered first and not counted (default 2)
#   --lpv MODE         geometry (its raster path, "GL 3.2 geometry shader"; default),
#                      compute (its GL 4.3 compute path) or off
#   --technique T      gather (default) or scatter
#   --sslpv 0|1        its subsurface volumes (default 1, its default)
#   --no-lpv-off       skip the second run with the LPV off (by default the
#                      whole frame is measured again with the LPV off, as
#                      `lpv bench render --thesis-settings` does)
#   --scene N          0 Sponza (its sponza.4ds is not in the snapshot), 1 Sibenik
#                      (default), 2 Motel
#   --timeout S        seconds per run before it is killed (default 900)
#   --log FILE         keep the application's whole console output in FILE
#   --shader-cache     let Mesa use its on-disk shader cache (by default it is
#                      off for this program: with a cache hit, Mesa 22.3.6's
#                      llvmpipe runs its shadow pass 2.3x slower, 197 against
#                      87 ms; ours measures the same either way)
#
# Output: one "phase NAME MS" line per phase (medians over FRAMES), names:
#   shadow_maps rsm lpv_clear injection propagation final_shading whole_frame
#   [lpv_off_whole_frame]
# and "#"-prefixed lines with the settings, renderer and min/max.
# Exit status: 0 when every run printed its medians, 1 otherwise, 2 on usage.
set -euo pipefail

usage() { sed -n '2,34p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

[ $# -ge 1 ] || usage
CHECKOUT=$1
shift
FRAMES=10
if [ $# -ge 1 ] && [[ $1 =~ ^[0-9]+$ ]]; then FRAMES=$1; shift; fi
WARMUP=2
LPV=geometry
TECHNIQUE=gather
SSLPV=1
LPV_OFF=1
SCENE=1
TIMEOUT=900
LOG=
SHADER_CACHE_DISABLE=true
while [ $# -gt 0 ]; do
    case $1 in
        --warmup) WARMUP=${2:?}; shift 2 ;;
        --lpv) LPV=${2:?}; shift 2 ;;
        --technique) TECHNIQUE=${2:?}; shift 2 ;;
        --sslpv) SSLPV=${2:?}; shift 2 ;;
        --no-lpv-off) LPV_OFF=0; shift ;;
        --scene) SCENE=${2:?}; shift 2 ;;
        --timeout) TIMEOUT=${2:?}; shift 2 ;;
        --log) LOG=${2:?}; shift 2 ;;
        --shader-cache) SHADER_CACHE_DISABLE=false; shift ;;
        -h|--help) usage ;;
        *) echo "run.sh: unknown option '$1'" >&2; usage ;;
    esac
done
case $LPV in geometry|compute|off) ;; *) echo "run.sh: --lpv is geometry, compute or off" >&2; exit 2 ;; esac
case $TECHNIQUE in gather|scatter) ;; *) echo "run.sh: --technique is gather or scatter" >&2; exit 2 ;; esac
[[ $FRAMES =~ ^[1-9][0-9]*$ && $WARMUP =~ ^[0-9]+$ && $SCENE =~ ^[0-2]$ && $SSLPV =~ ^[01]$ ]] ||
    { echo "run.sh: FRAMES >= 1, --warmup >= 0, --scene 0-2, --sslpv 0|1" >&2; exit 2; }

CHECKOUT=$(cd "$CHECKOUT" && pwd)
BIN=$CHECKOUT/bin/LightPropagationVolumes.exe
[ -x "$BIN" ] || { echo "run.sh: $BIN is missing: build the checkout first (README.md)" >&2; exit 1; }
grep -aq THESIS_BENCH_FRAMES "$BIN" ||
    { echo "run.sh: $BIN has no THESIS_BENCH_* hooks: apply the bench patch and rebuild (README.md)" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "run.sh: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }

# Its .4ds files name textures in upper case (found on Windows' case-insensitive
# file system); the snapshot's data/maps has them mostly in lower case.
if [ ! -e "$CHECKOUT/data/maps/SIBENIK_KAMEN.BMP" ]; then
    (cd "$CHECKOUT/data/maps" && for f in *; do
        u=$(printf '%s' "$f" | LC_ALL=C tr '[:lower:]' '[:upper:]')
        [ "$u" = "$f" ] || [ -e "$u" ] || ln -s "$f" "$u"
    done)
    echo "# made upper-case links in $CHECKOUT/data/maps (its models name textures in upper case)"
fi

[ -n "$LOG" ] && : > "$LOG"

# One run: prints the "BENCH median" lines of the application, or fails.
run_once() { # LPV-mode
    local out rc=0
    out=$(mktemp)
    (cd "$CHECKOUT" &&
        THESIS_BENCH_FRAMES=$FRAMES THESIS_BENCH_WARMUP=$WARMUP THESIS_BENCH_SCENE=$SCENE \
        THESIS_BENCH_LPV=$1 THESIS_BENCH_TECHNIQUE=$TECHNIQUE THESIS_BENCH_SSLPV=$SSLPV \
        timeout "$TIMEOUT" xvfb-run -a -s "-screen 0 1280x1024x24" \
            env LIBGL_ALWAYS_SOFTWARE=1 MESA_SHADER_CACHE_DISABLE=$SHADER_CACHE_DISABLE stdbuf -oL "$BIN") >"$out" 2>&1 || rc=$?
    if [ -n "$LOG" ]; then { echo "=== THESIS_BENCH_LPV=$1 (exit $rc)"; cat "$out"; } >>"$LOG"; fi
    grep -E '^(Renderer|Version):' "$out" | sed 's/^/# /' | sort -u
    grep '^BENCH settings' "$out" | sed 's/^BENCH /# /'
    if [ "$rc" -ne 0 ] || ! grep -q '^BENCH median total' "$out"; then
        echo "run.sh: the run with THESIS_BENCH_LPV=$1 failed (exit $rc); last lines:" >&2
        tail -n 15 "$out" >&2
        rm -f "$out"
        return 1
    fi
    grep '^BENCH median' "$out"
    rm -f "$out"
}

name_of() {
    case $1 in
        shadow) echo shadow_maps ;; rsm) echo rsm ;; lpv_clear) echo lpv_clear ;;
        injection) echo injection ;; propagation) echo propagation ;;
        final) echo final_shading ;; total) echo whole_frame ;; *) echo "$1" ;;
    esac
}

echo "# thesis application, $FRAMES frames after $WARMUP warm-up, lpv $LPV, technique $TECHNIQUE, sslpv $SSLPV, scene $SCENE, Mesa shader cache disabled: $SHADER_CACHE_DISABLE"
status=0
if res=$(run_once "$LPV"); then
    grep '^#' <<<"$res" || true
    # "BENCH median shadow 86.6 ms (min 85.3, max 87.5, 3 frames)"
    while read -r _ _ phase ms _ _ min _ max _; do
        echo "phase $(name_of "$phase") $ms"
        echo "#   $(name_of "$phase") min ${min%,} max ${max%,}"
    done < <(grep '^BENCH median' <<<"$res")
else
    status=1
fi
if [ "$LPV_OFF" = 1 ] && [ "$LPV" != off ]; then
    if res=$(run_once off); then
        echo "phase lpv_off_whole_frame $(grep '^BENCH median total' <<<"$res" | awk '{print $4}')"
    else
        status=1
    fi
fi
exit $status
