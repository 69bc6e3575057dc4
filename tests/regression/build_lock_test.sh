#!/usr/bin/env bash
# scripts/build takes one build at a time per build directory (a lock file in it): two calls at
# once on a build whose one step takes 2 s (a stand-in build.ninja in a scratch directory, so
# that nothing of the real build is touched) must both succeed, the second must say that it waits
# and then find nothing left to build, and together they take one build's time, not two
# overlapping ones. Usage: build_lock_test.sh SOURCE_DIR SCRATCH_DIR
set -euo pipefail
source_dir=$1
dir=$2
rm -rf "$dir"
mkdir -p "$dir/build"
build="$dir/build"
cat >"$build/build.ninja" <<'NINJA'
rule slow
  command = sleep 2 && echo built >> runs.txt && touch $out
build out.txt: slow
build plisse: phony out.txt
NINJA
: >"$build/.plisse-cmake-args"  # configured with no PLISSE_CMAKE_ARGS: no cmake run
export PLISSE_BUILD_DIR="$build"
unset PLISSE_CMAKE_ARGS
"$source_dir/scripts/build" plisse 2>"$dir/first.log" &
first=$!
sleep 0.5
"$source_dir/scripts/build" plisse 2>"$dir/second.log" &
second=$!
wait "$first" || { echo "FAIL: the first build failed"; cat "$dir/first.log"; exit 1; }
wait "$second" || { echo "FAIL: the second build failed"; cat "$dir/second.log"; exit 1; }
grep -q "building" "$dir/first.log" || { echo "FAIL: the first call did not build"; exit 1; }
grep -q "waiting for another build" "$dir/second.log" ||
  { echo "FAIL: the second call did not wait:"; cat "$dir/second.log"; exit 1; }
if grep -q "building" "$dir/second.log"; then
  echo "FAIL: the second call built again:"; cat "$dir/second.log"; exit 1
fi
runs=$(wc -l <"$build/runs.txt")
[[ "$runs" -eq 1 ]] || { echo "FAIL: the build step ran $runs times"; exit 1; }
# A third call, alone, neither waits nor builds.
"$source_dir/scripts/build" plisse 2>"$dir/third.log"
if [[ -s "$dir/third.log" ]]; then echo "FAIL: a call with nothing to do printed:"; cat "$dir/third.log"; exit 1; fi
echo "PASS: the second call waited and found the build done; the step ran once"
