#!/bin/bash
# The figures a machine with a GPU gives, in one run and one table:
#
#   tools/gpu/measure.sh [--quick] [--out DIR] [--stages LIST] [--references DIR]
#                        [--backend B] [--bench-timeout SECONDS] [--no-bench]
#
#   1. builds RayLab (cmake, Release) when build/raylab is missing;
#   2. renders every check view of every stage with the solution and compares
#      them with the committed pictures, tests/reference/<stage>/ (`raylab
#      check --solution --against`: the pictures of llvmpipe, the CI's
#      renderer, so a GPU that draws differently shows here);
#   3. runs `raylab bench` for both tracks at 800x600 and 1920x1080;
#   4. prints one table (DIR/measure.md), headed by the machine's GL strings.
#
# --quick: the same steps at the smallest settings (each track's `bench
# --quick`, 160x120): about two minutes on llvmpipe, so it works here the day
# a GPU is lent (tests/gpu/run_measure_test.sh runs it). --stages: a
# comma-separated subset (ids or numbers); --references: another folder laid
# out like tests/reference; --bench-timeout: stop each bench after SECONDS
# (a lent GPU's minutes are counted; the table says which ran out);
# --no-bench: the checks only. Exit
# status 0 when every check passed and every bench ran, 1 when something
# failed or ran out of time (the table says what), 2 for bad usage.
# RAYLAB overrides the binary (default build/raylab of this tree).
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; }
die() { echo "measure.sh: $*" >&2; exit 2; }

quick=0 out="" stages="" references="$here/tests/reference" backend=auto benchTimeout=0 benches=1
while [[ $# -gt 0 ]]; do
    case "$1" in
        --quick) quick=1 ;;
        --no-bench) benches=0 ;;
        --out) [[ $# -ge 2 ]] || die "--out needs a folder"; out=$2; shift ;;
        --stages) [[ $# -ge 2 ]] || die "--stages needs a list"; stages=$2; shift ;;
        --references) [[ $# -ge 2 ]] || die "--references needs a folder"; references=$2; shift ;;
        --backend) [[ $# -ge 2 ]] || die "--backend needs egl, osmesa or auto"; backend=$2; shift ;;
        --bench-timeout)
            [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || die "--bench-timeout needs a whole number of seconds"
            benchTimeout=$2; shift ;;
        -h|--help) usage; exit 0 ;;
        *) die "unknown option '$1' (see --help)" ;;
    esac
    shift
done
[[ -d $references ]] || die "no reference pictures in '$references'"
command -v python3 >/dev/null || die "python3 not found (it writes the table)"

raylab=${RAYLAB:-$here/build/raylab}
if [[ ! -x $raylab ]]; then
    [[ -z ${RAYLAB:-} ]] || die "RAYLAB=$raylab is not an executable"
    command -v cmake >/dev/null || die "build/raylab is missing and cmake is not installed (bash install.sh sets up a machine)"
    echo "measure.sh: building RayLab (build/, Release)" >&2
    { cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release &&
        cmake --build "$here/build" -j"$(nproc)" --target raylab; } >&2 || die "the build failed"
fi

# The stages, resolved before anything is written (ids or numbers).
if [[ -n $stages ]]; then
    IFS=',' read -ra wanted <<<"$stages"
else
    mapfile -t wanted < <("$raylab" stages | awk '/^  [0-9a-z]/ {print $1}')
fi
ids=()
for stage in "${wanted[@]}"; do
    id=$("$raylab" stages | awk -v s="$stage" '/^  / && ($1 == s || index($1, s "-") == 1) {print $1; exit}')
    [[ -n $id ]] || die "unknown stage '$stage' (see raylab stages)"
    [[ -d $references/$id ]] || die "no reference pictures for $id in '$references'"
    ids+=("$id")
done

if [[ -z $out ]]; then out=$(mktemp -d /tmp/raylab-gpu-XXXXXX); fi
mkdir -p "$out" || die "cannot make '$out'"
out=$(cd "$out" && pwd)
rm -rf "$out/checks" "$out"/bench-* "$out/gl.log" "$out/measure.md"
mkdir -p "$out/checks"
failed=0

# The GL strings: a one-frame demo prints them on its first line.
if ! "$raylab" demo --headless --backend "$backend" --stage 01 --frames 1 --size 64x48 \
    --out "$out/gl-frame" >"$out/gl.log" 2>&1; then
    echo "measure.sh: no GL context: $(tail -1 "$out/gl.log")" >&2
    exit 1
fi
rm -rf "$out/gl-frame"

# Every check view of every stage (or of --stages) against the references.
for id in "${ids[@]}"; do
    "$raylab" check --stage "$id" --solution --backend "$backend" \
        --against "$references/$id" >"$out/checks/$id.log" 2>&1
    echo $? >"$out/checks/$id.rc"
done

# Both tracks' benches: llvmpipe-sized in quick mode, both sizes otherwise.
# Without gnuplot (a lent GPU machine has none) the benches write no plot.
plot=()
command -v gnuplot >/dev/null || plot=(--no-plot)
bench() {  # NAME, then raylab bench options
    local name=$1
    shift
    set -- "$@" "${plot[@]}"
    local limit=()
    [[ $benchTimeout == 0 ]] || limit=(timeout --kill-after=10 "$benchTimeout")
    "${limit[@]}" "$raylab" bench --backend "$backend" --out "$out/bench-$name" "$@" \
        >"$out/bench-$name.log" 2>&1
    local rc=$?
    if [[ $rc == 124 || $rc == 137 ]]; then
        echo "ran out of time: --bench-timeout $benchTimeout" >>"$out/bench-$name.log"
        mkdir -p "$out/bench-$name"
    fi
    if [[ $rc != 0 ]]; then
        echo "measure.sh: raylab bench $* failed: $(tail -1 "$out/bench-$name.log")" >&2
        failed=1
    fi
}
if [[ $benches == 0 ]]; then
    :
elif [[ $quick == 1 ]]; then
    bench raytrace-quick --quick
    bench fur-quick --track fur --quick
else
    for size in 800x600 1920x1080; do
        bench "raytrace-$size" --size "$size"
        bench "fur-$size" --track fur --size "$size"
    done
fi

python3 "$here/tools/gpu/summarise.py" "$out" "$references" >"$out/measure.md" || failed=1
cat "$out/measure.md"
grep -q '^| .* | FAIL |' "$out/measure.md" && failed=1
echo "measure.sh: the table is $out/measure.md; logs and bench folders beside it" >&2
exit $failed
