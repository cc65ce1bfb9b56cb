#!/usr/bin/env bash
# The main job: install, build, and run the Hodge decomposition demo on CGAL's
# elephant (or on the mesh given as first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh --target hodge_decomposition_demo
mkdir -p output
./build/examples/tangent_vector_fields/hodge_decomposition_demo "${1:-build/cgal-data/data/meshes/elephant.off}" output/hodge_demo
