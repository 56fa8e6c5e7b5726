#!/usr/bin/env bash
# The README's first command: set up, build the demo with the layer and the simulated runtime, and run it on
# the built-in default room. The demo is a real OpenXR app: it goes through the Khronos loader, the headless
# simulated runtime and the implicit roomsense layer, which it finds beside itself in build/ (no environment
# needed). Arguments go to the demo: scripts/demo.sh ROOMFILE analyses another room (roomsense-demo --help).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOMSENSE_TARGET=roomsense-demo scripts/setup.sh build
build/bin/roomsense-demo --output demo-output "$@"
