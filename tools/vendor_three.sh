#!/bin/sh
# Rebuild src/rbi/viz/vendor/three/three.bundle.min.js from the npm registry's `three` package
# (with its OrbitControls addon) as one minified script defining the global THREE.
# Usage: tools/vendor_three.sh [VERSION]   (run from the project root; needs node and npm)
set -eu
VERSION="${1:-0.187.0}"
ROOT="$(pwd)"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
npm init -y >/dev/null
npm install --silent "three@$VERSION" esbuild
printf "export * from 'three';\nexport { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';\n" > entry.js
npx esbuild entry.js --bundle --format=iife --global-name=THREE --minify --legal-comments=inline \
    --outfile="$ROOT/src/rbi/viz/vendor/three/three.bundle.min.js"
cp node_modules/three/LICENSE "$ROOT/src/rbi/viz/vendor/three/LICENSE"
echo "three $VERSION bundled"
