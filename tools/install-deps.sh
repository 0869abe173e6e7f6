#!/bin/sh
# Installs the build and test dependencies from Debian 12 packages (as root, or through
# sudo). Does nothing when every package is already installed.
# chromium: the test that `compare report` pages open in a browser with every image loaded
# (tests/compare/report_browser.sh, headless); without it that test is skipped.
set -eu
PACKAGES="cmake g++ make pkg-config libtinyxml2-dev libpng-dev libjpeg62-turbo-dev zlib1g-dev ocl-icd-opencl-dev
  opencl-c-headers opencl-clhpp-headers pocl-opencl-icd clinfo libgtest-dev libopenexr-dev
  libopenmpi-dev openmpi-bin libassimp-dev nlohmann-json3-dev assimp-testmodels clang
  libclang-rt-14-dev libembree-dev python3 chromium"
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "installing:$missing"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
