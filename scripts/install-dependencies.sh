#!/usr/bin/env bash
# Installs the build and run-time dependencies from Debian 12's packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  build-essential cmake
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libboost-program-options-dev               # the command-line tool tvf
  libeigen3-dev
  nlohmann-json3-dev                         # JSON: constraint files and the editor's messages
  libsuitesparse-dev libopenblas0-pthread   # CHOLMOD, with OpenBLAS as its BLAS (about 3x faster than the reference BLAS)
  libgtest-dev
  libcairo2-dev pkg-config fonts-dejavu-core # pictures: Field_renderer (PNG, SVG) and its text
  libfreetype-dev                            # glyph outlines read from fonts (Spline_approximation, tvf fit --glyph): exact Bezier truth
  libcgal-demo                               # CGAL's data tree: the default mesh and the test meshes
  chromium                                   # the editor's end-to-end test (headless)
  clang libclang-rt-14-dev                   # the fuzzers (scripts/fuzz.sh): libFuzzer, ASan and UBSan runtimes
)
# The editor page is bundled with npm; a node already on PATH (say, a newer one from
# elsewhere) is kept rather than replaced by Debian's.
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs npm); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
