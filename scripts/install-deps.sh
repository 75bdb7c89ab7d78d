#!/usr/bin/env bash
# Installs everything a fresh Debian 12 machine needs (the one apt-get line of the README).
# Never installs libvtk9-dev / python3-vtk9: they conflict with python3-paraview.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PACKAGES="cmake g++ make paraview paraview-dev python3-paraview python3-dev \
  mpi-default-dev libx11-dev libglew-dev libpng-dev libjpeg-dev libtiff-dev libfreetype-dev \
  liblzma-dev liblz4-dev libdouble-conversion-dev libutfcpp-dev \
  libopenexr-dev libglm-dev doctest-dev nlohmann-json3-dev libcli11-dev xvfb xauth \
  clang-format-14 clang-tidy-14 python3-yt mpi-default-bin python3-numpy python3-scipy \
  python3-matplotlib"
# Skip apt entirely when everything is already there (fast CI re-runs).
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "install-deps: installing:$missing"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends $PACKAGES
else
  echo "install-deps: all packages present"
fi
