#!/usr/bin/env bash
# Installs the Debian packages lcmtf builds and tests with, only those that are missing.
# With --tests it also installs what only the tests use: ROS tf2 (libtf2-dev, with the
# geometry_msgs and tf2_geometry_msgs headers and KDL's), which the agreement tests check lcmtf
# against, its Python binding for the Python benchmark's comparison, pytest, Valgrind, and Xvfb
# with a Java that draws windows, under which the lcm-spy tables are drawn, and Chromium with a
# WebSocket client for Python, which drive the viewer's page. Nothing lcmtf builds for users
# links them.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev
  libeigen3-dev liburdfdom-dev libtinyxml-dev libcli11-dev libyaml-cpp-dev graphviz
  libgtest-dev libgmock-dev libbenchmark-dev
  default-jdk-headless libjchart2d-java
  clang libclang-rt-14-dev
  python3 python3-dev pybind11-dev python3-pybind11 python3-numpy
  libboost-dev nlohmann-json3-dev libjs-three
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(libtf2-dev libgeometry-msgs-dev libtf2-geometry-msgs-dev liborocos-kdl-dev
    python3-pytest python3-tf2 valgrind xvfb xauth default-jre chromium python3-websocket)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null | grep -qx installed; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
"${sudo[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
