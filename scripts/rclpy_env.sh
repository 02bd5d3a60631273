#!/usr/bin/env bash
# rclpy without a ROS installation: the ROS 2 Jazzy wheels from PyPI in a venv,
# and this package's interfaces (msg/, srv/) built against them with colcon,
# together with the standard types the wheels lack (tf2_msgs/TFMessage and the
# simulation_interfaces services the node serves: tests/rclpy/interfaces/).
#
#   scripts/rclpy_env.sh [--with-node]
#   . target/rclpy-ws/env.sh        # then: python3 launch-scripts/brake_load_example.py
#
# Idempotent: the venv (target/rclpy-venv, or $RCLPY_VENV) is installed from
# scripts/rclpy-requirements.txt only when that file changed; the colcon
# workspace (target/rclpy-ws, or $RCLPY_WS) is rebuilt only when its inputs
# (package.xml, CMakeLists.txt, msg/, srv/, tests/rclpy/interfaces/, the
# requirements, this script) changed. --with-node also builds and installs the
# node (cargo build --release into the checkout's target/, then
# `ros2 run`-style lib/annular_plate/annular_plate); without it only the
# interfaces are built (cmake -DANNULAR_PLATE_BUILD_NODE=OFF).
# Needs python3.11 with venv and its headers (Python.h), a C/C++ compiler and
# PyPI access. Prints the time each part took.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv=${RCLPY_VENV:-$repo/target/rclpy-venv}
ws=${RCLPY_WS:-$repo/target/rclpy-ws}
host_python=${PYTHON:-python3}
build_node=OFF
for a in "$@"; do
  case $a in
    --with-node) build_node=ON ;;
    -h | --help) sed -n '2,21p' "$0"; exit 0 ;;
    *) echo "rclpy_env.sh: unknown argument $a" >&2; exit 2 ;;
  esac
done
req=$repo/scripts/rclpy-requirements.txt
die() { echo "rclpy_env.sh: $*" >&2; exit 1; }
now() { date +%s.%N; }
took() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

mkdir -p "$ws"
# One setup at a time (two test binaries, or a user and a test).
exec 9>"$ws.lock"
flock 9

# 1. The venv, from the pinned requirements.
t0=$(now)
if ! cmp -s "$req" "$venv/requirements.installed" \
  || ! "$venv/bin/python" -c 'import rclpy, rosbags, numpy, colcon_core' >/dev/null 2>&1; then
  "$host_python" -c 'import sys; assert sys.version_info[:2] == (3, 11), sys.version' 2>/dev/null \
    || die "$host_python is not Python 3.11 (the Jazzy wheels on PyPI are cp311); set PYTHON=python3.11"
  if [ ! -x "$venv/bin/python" ]; then
    rm -rf "$venv"
    "$host_python" -m venv "$venv" || die "cannot create the venv $venv (python3-venv installed?)"
  fi
  "$venv/bin/python" -m pip install --disable-pip-version-check -q -r "$req" \
    || die "pip install -r scripts/rclpy-requirements.txt failed"
  cp "$req" "$venv/requirements.installed"
  echo "rclpy_env.sh: venv $venv installed in $(took "$t0") s"
fi

# 2. The wheels' CMake exports name the wheel builder's Python and numpy
#    include directories; point them at this venv's (else CMake: "includes
#    non-existent path"). Idempotent.
pyinc=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')
npinc=$("$venv/bin/python" -c 'import numpy; print(numpy.get_include())')
[ -f "$pyinc/Python.h" ] || die "no Python.h in $pyinc: install Python 3.11's headers (python3-dev)"
sed -i -e "s#/opt/python/cp3[0-9]*-cp3[0-9]*/include/python3\.[0-9]*#$pyinc#g" \
  -e "s#/opt/python/[^;\"]*/numpy/_core/include#$npinc#g" \
  "$venv"/share/*/cmake/*__rosidl_generator_pyExport.cmake

# 3. The colcon workspace: src links the checkout and the two interface packages
#    (the venv stays outside it: colcon would crawl it).
mkdir -p "$ws/src"
ln -sfn "$repo" "$ws/src/annular_plate"
ln -sfn "$repo/tests/rclpy/interfaces/tf2_msgs" "$ws/src/tf2_msgs"
ln -sfn "$repo/tests/rclpy/interfaces/simulation_interfaces" "$ws/src/simulation_interfaces"
inputs=$(
  cd "$repo"
  {
    echo "node=$build_node venv=$venv"
    sha256sum "$req" scripts/rclpy_env.sh package.xml CMakeLists.txt msg/* srv/*
    find tests/rclpy/interfaces -type f | LC_ALL=C sort | xargs sha256sum
  } | sha256sum | cut -d' ' -f1
)
stamp=$ws/inputs.sha256
if [ "$build_node" = ON ] || ! cmp -s <(echo "$inputs") "$stamp" || [ ! -f "$ws/install/setup.sh" ]; then
  t1=$(now)
  rm -f "$stamp"
  (
    set +u
    # shellcheck disable=SC1091
    . "$venv/bin/activate"
    export AMENT_PREFIX_PATH=$venv
    cd "$ws"
    colcon build --base-paths src \
      --cmake-args -DANNULAR_PLATE_BUILD_NODE="$build_node" -DBUILD_TESTING=OFF >"$ws/build.log" 2>&1
  ) || { tail -n 60 "$ws/build.log" >&2; die "colcon build failed (whole log: $ws/build.log)"; }
  echo "$inputs" >"$stamp"
  echo "rclpy_env.sh: colcon build (node: $build_node) in $(took "$t1") s"
fi

# 4. What a shell (or a test) sources to use it.
cat >"$ws/env.sh" <<EOF
# Source this (bash or sh): rclpy from $venv and the interfaces built in $ws.
# Written by scripts/rclpy_env.sh.
case \$- in *u*) _rclpy_env_u=1 ;; *) _rclpy_env_u= ;; esac
set +u  # colcon's setup.sh reads unset variables
. "$venv/bin/activate"
. "$ws/install/setup.sh"
export AMENT_PREFIX_PATH="\$AMENT_PREFIX_PATH:$venv"
export RMW_IMPLEMENTATION=\${RMW_IMPLEMENTATION:-rmw_fastrtps_cpp}
[ -n "\$_rclpy_env_u" ] && set -u
unset _rclpy_env_u
EOF
echo "rclpy_env.sh: ready in $(took "$t0") s; use it with: . $ws/env.sh"
