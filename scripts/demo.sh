#!/usr/bin/env bash
# The README's first command: set up, build, and analyse the built-in default room.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOMSENSE_TARGET=roomsense scripts/setup.sh build
mkdir -p demo-output
build/tools/roomsense/roomsense analyze synthetic:default --bounds demo-output/bounds.obj
build/tools/roomsense/roomsense analyze synthetic:default --json demo-output/analysis.json --bounds demo-output/bounds.glb
echo "wrote demo-output/analysis.json, demo-output/bounds.obj and demo-output/bounds.glb"
