#!/usr/bin/env bash
# Install dependencies, build, and run the whole test suite: unit tests, server tests on a
# real server process, validation against Hopsan's reference results in ../shared, and the
# web app's unit and browser tests (Debian's Chromium). Then the same tests and the fuzz
# targets under ASan+UBSan, and the same tests again under TSan (the multi-threaded
# simulation, the job queue, and the server's I/O threads and workers, in process and in the
# server processes the tests start); the sanitizer stages leave out the web app, the shared
# models, validation, the Python client (it drives the same routes the server tests do) and
# the multi-process scale-out faults. Each stage prints its wall time.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

stage() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "stage $name: $((SECONDS - start)) s"
}

# Sanitizer builds: clang 14, -O1 with debug info, no benchmarks, no web app.
sanitizer_config() {
  local dir=$1
  shift
  cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DTLMHUB_BUILD_BENCHMARKS=OFF "$@" >/dev/null
}
asan_build() {
  # One build for tests and fuzz targets: everything has coverage instrumentation.
  sanitizer_config build-asan -DTLMHUB_SANITIZE=address,undefined -DTLMHUB_FUZZ=ON
  cmake --build build-asan -j"$jobs"
}
tsan_build() {
  sanitizer_config build-tsan -DTLMHUB_SANITIZE=thread
  cmake --build build-tsan -j"$jobs" --target tlmhub-tests tlmhub-server-tests tlmhub-store-tests tlmhub-cli \
    tlmhub-cli-tests tlmhub-fmu-tests
}
# A race aborts the process that has it, so one in a server started by a test fails that test.
tsan_test() {
  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
    ctest --test-dir build-tsan --output-on-failure -j"$jobs" -LE '^(web|models|validation|scaleout|python)$'
}

stage install scripts/install-deps.sh --with-browser --with-clang
stage build scripts/build.sh
stage test ctest --test-dir build --output-on-failure -j"$jobs"
stage asan-build asan_build
stage asan-test ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE '^(web|models|validation|scaleout|python)$'
stage tsan-build tsan_build
stage tsan-test tsan_test
