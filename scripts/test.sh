#!/usr/bin/env bash
# Install dependencies, build, and run the whole test suite: unit tests, server tests on a
# real server process, validation against Hopsan's reference results in ../shared, and the
# web app's unit and browser tests (Debian's Chromium). Then the tests that start threads or
# child processes (label threads: the multi-threaded simulation, the job queue, the server's
# I/O threads and workers, in process and in the server processes the tests start) under
# TSan, and the same tests as Release and the fuzz targets under ASan+UBSan; the sanitizer
# stages leave out the web app, the shared models, validation, the Python client (it drives
# the same routes the server tests do) and the multi-process scale-out faults.
#
# Each stage prints its wall time; each build its slowest compiles and links; each test
# stage its 15 slowest tests, and it fails when a test listed in tests/ci-expected-STAGE.txt
# did not run (or one ran that is not listed). The whole run should stay within 45 minutes
# on CI's 2 cores: the script warns when it does not.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
jobs=$(nproc)
budget_seconds=$((45 * 60))
# Ninja starts a target's compiles before its dependencies are linked, which keeps both
# cores busy where make waits. Only a new build directory takes it.
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}

# Scratch files (the tests' databases and server directories, PostgreSQL clusters, unzipped
# FMUs, compiler temporaries) on tmpfs where there is one with room that may hold programs (the
# FMU tests load libraries from it): on CI's disk, creating and deleting the files of a
# PostgreSQL database per store test cost more system time than the tests' own work
# (StoreConformance.postgres: 39 s on disk, 29 s on tmpfs). World-searchable, as /tmp is:
# PostgreSQL runs as nobody under it.
use_tmpfs_scratch() {
  [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ] || return 0
  [ "$(df --output=avail -k /dev/shm | tail -1)" -gt $((4 * 1024 * 1024)) ] || return 0
  local dir
  dir=$(mktemp -d /dev/shm/tlmhub-test.XXXXXX)
  printf '#!/bin/sh\n' >"$dir/exec-probe"
  chmod +x "$dir/exec-probe"
  if ! "$dir/exec-probe" 2>/dev/null; then
    rm -rf "$dir"
    return 0
  fi
  rm "$dir/exec-probe"
  chmod 1777 "$dir"
  export TMPDIR=$dir
  scratch_dir=$dir
}
scratch_dir=
declare -A background_pids=()
# On any exit: stop the builds still running in the background, then remove the scratch files.
cleanup() {
  local pid
  for pid in "${background_pids[@]}"; do
    # The group, or the process itself if it has not yet made its group.
    kill -TERM -- "-$pid" 2>/dev/null || kill -TERM "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  [ -z "$scratch_dir" ] || rm -rf "$scratch_dir"
}
trap cleanup EXIT
use_tmpfs_scratch

# The machine's busy and total CPU time so far, in clock ticks (/proc/stat: busy is all but
# idle and iowait), as "busy total".
machine_ticks() {
  awk '/^cpu / {print $2 + $3 + $4 + $7 + $8 + $9, $2 + $3 + $4 + $5 + $6 + $7 + $8 + $9}' /proc/stat
}
# Prints a stage's wall time and the CPU time of everything it ran (user + system of the
# processes it waited for), and how many cores the whole machine kept busy meanwhile (a build
# running beside the stage included): below the core count, CPU went unused.
stage() {
  local name=$1
  shift
  local TIMEFORMAT="stage $name: %0R s (CPU %0U s user + %0S s system)" before
  before=$(machine_ticks)
  # Not `time ... || status=$?`: a function called on the left of || runs without errexit.
  time "$@"
  echo "$before $(machine_ticks)" | awk -v name="$name" -v cores="$jobs" \
    '$4 > $2 {printf "stage %s: the machine kept %.2f of %d cores busy\n", name, cores * ($3 - $1) / ($4 - $2), cores}'
}

# Every compile and link of build directory $1 is timed into $1/build-times.tsv: sets the
# array `timing` to the CMake flags that do it.
timing_flags() {
  local log=$root/$1/build-times.tsv
  mkdir -p "$1"
  : >"$log"
  timing=("-DCMAKE_CXX_COMPILER_LAUNCHER=$root/scripts/ci/time-command;$log"
          "-DCMAKE_CXX_LINKER_LAUNCHER=$root/scripts/ci/time-command;$log")
}
slowest_build_steps() {
  awk -F '\t' -v dir="$1" '{cpu += $1} END {printf "compiles and links in %s: %.0f s of CPU\n", dir, cpu}' \
    "$1/build-times.tsv"
  echo "the slowest (CPU seconds, wall seconds):"
  # sed reads to the end: head would close the pipe early, and under pipefail sort's
  # SIGPIPE (exit 141) once failed a whole CI run.
  sort -rn "$1/build-times.tsv" | sed -n "1,12{s|$root/||; s|^|  |; p}"
}

# Runs ctest in build directory $2 with JUnit output, then checks the names that ran
# against tests/ci-expected-$1.txt (scripts/ci/test_report.py).
run_tests() {
  local name=$1 dir=$2
  shift 2
  local reports=$root/$dir/test-reports status=0
  rm -rf "$reports"
  mkdir -p "$reports"
  TLMHUB_TEST_REPORT_DIR=$reports ctest --test-dir "$dir" --output-on-failure \
    --output-junit "$reports/ctest.xml" --test-output-size-passed 1000000 "$@" || status=$?
  python3 scripts/ci/test_report.py --stage "$name" --junit "$reports/ctest.xml" --reports "$reports" \
    --expected "tests/ci-expected-$name.txt" || status=1
  return $status
}

# No Google Benchmark programs: no test runs them (bench/README.md builds them).
release_build() {
  timing_flags build
  scripts/build.sh "${timing[@]}" -DTLMHUB_BUILD_BENCHMARKS=OFF
  slowest_build_steps build
  # The OpenID provider and the LTI platform the sign-in tests start (tests/peers/, label sso).
  npm ci --prefix tests/peers/oidc-provider --no-audit --no-fund
  npm ci --prefix tests/peers/lti-platform --no-audit --no-fund
}

# Sanitizer builds: clang 14, -O1 with line tables (enough for file:line in every report),
# no benchmarks, no web app.
sanitizer_config() {
  local dir=$1
  shift
  timing_flags "$dir"
  cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DTLMHUB_BUILD_BENCHMARKS=OFF \
        "${timing[@]}" "$@" >/dev/null
}
asan_build() {
  # One build for tests and fuzz targets: the code under test has coverage instrumentation.
  sanitizer_config build-asan -DTLMHUB_SANITIZE=address,undefined -DTLMHUB_FUZZ=ON
  cmake --build build-asan -j"$jobs"
  slowest_build_steps build-asan
}
tsan_build() {
  sanitizer_config build-tsan -DTLMHUB_SANITIZE=thread
  cmake --build build-tsan -j"$jobs" --target tlmhub-tests tlmhub-server-tests tlmhub-store-tests tlmhub-cli \
    tlmhub-cli-tests tlmhub-fmu-tests
  slowest_build_steps build-tsan
}
# Release tests, with tests/tools/thread_probe.c noting which tests start threads or child
# processes: each of those must have the label `threads` (the TSan stage runs only that label).
release_test() {
  local probes=$root/build/thread-probe status=0
  rm -rf "$probes"
  mkdir -p "$probes"
  cc -shared -fPIC -O2 -o build/thread_probe.so tests/tools/thread_probe.c -ldl
  LD_PRELOAD=$root/build/thread_probe.so TLMHUB_THREAD_PROBE_DIR=$probes run_tests test build -j"$jobs" || status=$?
  python3 scripts/ci/check_threads_label.py build "$probes" || status=1
  return $status
}
sanitizer_excluded='^(web|models|validation|scaleout|python)$'
asan_test() {
  run_tests asan-test build-asan -j"$jobs" -LE "$sanitizer_excluded"
}
# Only the tests that start threads or child processes (label threads): a race needs two
# threads. A race aborts the process that has it, so one in a server started by a test
# fails that test.
tsan_test() {
  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
    run_tests tsan-test build-tsan -j"$jobs" -L '^threads$' -LE "$sanitizer_excluded"
}

# A sanitizer build runs beside the test stage before it, in the idle scheduling class
# (SCHED_IDLE): it gets only the CPU the tests leave, which is much of it, since they wait on
# sockets, servers and the browser, and a test thread that wakes takes its core back at once.
# Its output is printed when it ends; its wall time counts from its start. One at a time: with
# both sanitizer builds beside the Release tests, the cores were busy all along but the run
# took 3006 s instead of 2771 (the TSan build ended 723 s after those tests instead of 268 s,
# and every test stage ran slower beside two compiles than beside one).
start_background_stage() {
  # Job control puts it in a process group of its own, which cleanup() stops as a whole. Not
  # setsid: a new session is a scheduling group of its own (autogroup), which the kernel weighs
  # as an equal of the tests' whole group, idle class or not (seen: the Release tests 37 % slower).
  set -m
  bash -c 'chrt --idle -p 0 $$ >/dev/null && exec bash "$@"' background \
    "$root/scripts/test.sh" --background-stage "$1" >"$root/build/$1.log" 2>&1 &
  background_pids[$1]=$!
  set +m
}
finish_background_stage() {
  local status=0
  wait "${background_pids[$1]}" || status=$?
  unset "background_pids[$1]"
  cat "$root/build/$1.log"
  if [ "$status" -ne 0 ]; then
    echo "stage $1 failed (exit $status)"
    return "$status"
  fi
}
# scripts/test.sh --background-stage NAME: one build stage, as start_background_stage runs it.
if [ "${1:-}" = --background-stage ]; then
  trap - EXIT
  case $2 in
    tsan-build) stage "tsan-build (beside the Release tests, idle priority)" tsan_build ;;
    asan-build) stage "asan-build (beside the TSan tests, idle priority)" asan_build ;;
    *) echo "unknown background stage: $2" >&2; exit 2 ;;
  esac
  exit 0
fi

stage install scripts/install-deps.sh --with-browser --with-clang
stage build release_build
start_background_stage tsan-build
stage test release_test
finish_background_stage tsan-build
start_background_stage asan-build
stage tsan-test tsan_test
finish_background_stage asan-build
stage asan-test asan_test
echo "total: $SECONDS s"
if [ "$SECONDS" -gt "$budget_seconds" ]; then
  echo "WARNING: scripts/test.sh took $SECONDS s, over its budget of $budget_seconds s (45 minutes; CI stops at 90):" \
       "find what grew in the stage times and slowest tests above"
fi
