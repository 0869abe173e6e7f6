#!/bin/sh
# Installs the dependencies, builds the release binaries into build/, and renders the
# bundled example scene to build/example.png (inside build/, which git ignores, so a fresh
# clone stays clean).
set -eu
cd "$(dirname "$0")"
./tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/raytracer scenes/example.xml --output-dir build --stats
