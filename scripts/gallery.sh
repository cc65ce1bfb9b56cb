#!/usr/bin/env bash
# Regenerates the pictures in doc/tangent_vector_fields/gallery/ with the command-line tool: builds tvf if
# needed, then decomposes, filters, designs and draws fields on CGAL's elephant (and a
# torus knot for a harmonic field).  Intermediate fields and bases go to build/gallery/.
# Needs the dependencies of scripts/test.sh (run that, or scripts/demo.sh, once first).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh --target tvf >/dev/null

tvf=build/tvf
meshes=build/cgal-data/data/meshes
elephant=$meshes/elephant.off
knot=$meshes/knot1.off
gallery=doc/tangent_vector_fields/gallery
work=build/gallery
mkdir -p "$gallery" "$work"
# One camera for the elephant: from the side, a little above; y is up.
view=(--azimuth 0 --elevation 10 --width 800 --height 600)
small=(--azimuth 0 --elevation 10 --width 400 --height 300 --no-legend --line-width 0.9 --separation 0.025)

echo "1. Hodge decomposition of the demo field (a wind, a swirl and a source)"
$tvf decompose $elephant --demo-field -q --save-field $work/field.tvf --exact $work/exact.tvf \
  --coexact $work/coexact.tvf --harmonic $work/harmonic.tvf
$tvf render $elephant -q --field $work/exact.tvf --color divergence --streamlines "${view[@]}" \
  --title "curl-free part: streamlines over its divergence" -o $gallery/hodge_exact.png
$tvf render $elephant -q --field $work/coexact.tvf --color curl --fur --strokes 4000 --length 0.03 \
  --line-width 1.4 "${view[@]}" --title "divergence-free part: fur over its curl" -o $gallery/hodge_coexact.png
$tvf render $elephant -q --field $work/harmonic.tvf --color magnitude --clip 0.1 --streamlines "${view[@]}" \
  --title "harmonic part: it lives on the handles (genus 3)" -o $gallery/hodge_harmonic.png

echo "2. A harmonic field of a torus knot (genus 1)"
$tvf basis $knot -n 12 -q -o $work/knot.tvfb
$tvf eigenfield $knot -q --basis $work/knot.tvfb -k 1 -o $work/knot_harmonic.tvf
$tvf render $knot -q --field $work/knot_harmonic.tvf --color magnitude --streamlines --separation 0.015 \
  --azimuth 0 --elevation 30 --width 800 --height 600 --title "a harmonic field of a torus knot" \
  -o $gallery/knot_harmonic.png

echo "3. Eigenfields of the Hodge-Laplacian (the 300 lowest, a progress bar on terminals)"
$tvf basis $elephant -n 300 -q -o $work/elephant.tvfb
for k in 6 7 40 41; do
  $tvf eigenfield $elephant --basis $work/elephant.tvfb -k $k -o $work/eigenfield_$k.tvf > $work/eigenfield_$k.txt
  # "element 7: exact (curl-free), eigenvalue 5.91419 (lambda * area = 7.36293)"
  type=$(grep -oE 'coexact|exact|harmonic' $work/eigenfield_$k.txt | head -1)
  value=$(sed -E 's/.*lambda \* area = ([0-9.]+).*/\1/' $work/eigenfield_$k.txt | head -1)
  colour=divergence
  if [ "$type" = coexact ]; then colour=curl; fi
  $tvf render $elephant -q --field $work/eigenfield_$k.tvf --color $colour --streamlines "${small[@]}" \
    --title "$type, λ·area = $(printf '%.4g' "$value")" -o $gallery/eigenfield_$k.png
done

echo "4. A designed field: vectors, a source and a vortex (doc/tangent_vector_fields/gallery/elephant_constraints.json)"
$tvf design $elephant --constraints $gallery/elephant_constraints.json -q -o $work/designed.tvf
$tvf render $elephant -q --field $work/designed.tvf --color curl --streamlines "${view[@]}" \
  --title "designed: 10 vectors, a source and a vortex" -o $gallery/designed.png

echo "5. The designed field, low-pass filtered in the basis"
$tvf filter $elephant --basis $work/elephant.tvfb --field $work/designed.tvf --low-pass 0.02 -q \
  -o $work/designed_low_pass.tvf
$tvf render $elephant -q --field $work/designed_low_pass.tvf --color curl --streamlines "${view[@]}" \
  --title "low-pass exp(-0.02 λ·area): the vortex is spread out" -o $gallery/designed_low_pass.png

ls -l $gallery/*.png

echo "7. n-direction fields: hatching of cross and line fields, singular vertices marked"
nview=(--azimuth 0 --elevation 10 --width 800 --height 600 --separation 0.012)
fandisk=$meshes/fandisk.off
$tvf smoothest $fandisk --n 4 --align-curvature --alignment-weight 10 -q -o $work/fandisk_cross.rawfield
$tvf render $fandisk --n 4 --field $work/fandisk_cross.rawfield -q --streamlines --azimuth 35 --elevation 25 \
  --width 800 --height 600 --separation 0.01 --title "smoothest cross field aligned to the curvature (genus 0)" \
  -o $gallery/n_fandisk_cross.png
$tvf smoothest $elephant --n 4 -q -o $work/elephant_cross.rawfield
$tvf render $elephant --n 4 --field $work/elephant_cross.rawfield -q --streamlines "${nview[@]}" \
  --title "smoothest cross field (genus 3: indices sum to 4 chi = -16)" -o $gallery/n_elephant_cross.png
$tvf design $elephant --constraints $gallery/elephant_line_constraints.json -q -o $work/elephant_line.rawfield
$tvf render $elephant --n 2 --field $work/elephant_line.rawfield -q --streamlines --singularity-labels "${nview[@]}" \
  --title "line field: +1/2 and -1/2 prescribed, 4 vectors" -o $gallery/n_elephant_line.png
for order in 1 2; do
  $tvf design $elephant --constraints $gallery/elephant_cross_constraints.json --order $order -q \
    -o $work/elephant_cross_order$order.rawfield
done
$tvf render $elephant --n 4 --field $work/elephant_cross_order1.rawfield -q --streamlines "${nview[@]}" \
  --title "8 crosses, first-order design (min E_D)" -o $gallery/n_first_order.png
$tvf render $elephant --n 4 --field $work/elephant_cross_order2.rawfield -q --streamlines "${nview[@]}" \
  --title "8 crosses, higher-order spline (min E_B)" -o $gallery/n_higher_order.png
