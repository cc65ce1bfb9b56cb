// Colour maps as 256-entry tables in linear RGB (three.js blends vertex colours in linear
// space), built once from a few sRGB control points.

function srgbToLinear(c) {
  return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
}

function table(stops) {
  const lut = new Float32Array(256 * 3);
  for (let i = 0; i < 256; ++i) {
    const t = (i / 255) * (stops.length - 1);
    const k = Math.min(Math.floor(t), stops.length - 2);
    const u = t - k;
    for (let c = 0; c < 3; ++c) {
      const srgb = (stops[k][c] * (1 - u) + stops[k + 1][c] * u) / 255;
      lut[3 * i + c] = srgbToLinear(srgb);
    }
  }
  return lut;
}

// Viridis at nine points: magnitudes (0 dark, 1 bright).
export const VIRIDIS = table([
  [68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
  [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37],
]);

// Moreland's cool-warm at seven points: signed values, white-ish at 0.
export const COOL_WARM = table([
  [59, 76, 192], [103, 136, 238], [154, 186, 255], [221, 221, 221],
  [246, 183, 156], [234, 123, 96], [180, 4, 38],
]);

// Writes the colour of t in [0, 1] into out at offset o.
export function colourAt(lut, t, out, o) {
  const i = 3 * Math.max(0, Math.min(255, Math.round(t * 255)));
  out[o] = lut[i];
  out[o + 1] = lut[i + 1];
  out[o + 2] = lut[i + 2];
}

// A CSS gradient of the map, for the legend.
export function cssGradient(name) {
  const stops = name === 'magnitude'
    ? ['#440154', '#3b518b', '#21908d', '#5cc863', '#fde725']
    : ['#3b4cc0', '#9abaff', '#dddddd', '#f6b79c', '#b40426'];
  return `linear-gradient(to right, ${stops.join(', ')})`;
}
