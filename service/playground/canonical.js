// The inset of the canonical map (Stone & DeRose 1989, as drawn in Pomax's "A Primer on
// Bézier Curves", section "The canonical form"): the affine map sending P0, P1, P2 of a
// cubic to (0,0), (0,1), (1,1); the region where P3's image (x, y) falls is the type.
// The regions are painted here from their edge formulas (a fixed chart, the same for
// every cubic); the point on it and the type written beside it are the /classify
// answer's `canonical_point` and `type`.
//
// Edges: cusp y = (-x^2 + 2x + 3)/4 (x <= 1); loop closing at t = 0:
// y = (-x^2 + 3x)/3 (x <= 0); loop closing at t = 1: y = (sqrt(3(4x - x^2)) - x)/2
// (0 <= x <= 1); inflection at t = 1: y = 1. Each edge is named beside its line.

export const kWindow = Object.freeze({x0: -3.5, x1: 2.5, y0: -3, y1: 3});

const kRegionColors = {
  'arch': [226, 234, 246],
  'single-inflection': [223, 241, 217],
  'double-inflection': [251, 236, 205],
  'loop': [246, 214, 214],
};

const cuspEdge = (x) => (-x * x + 2 * x + 3) / 4;
const loopStartEdge = (x) => (-x * x + 3 * x) / 3;
const loopEndEdge = (x) => (Math.sqrt(3 * (4 * x - x * x)) - x) / 2;

/** The chart's region at (x, y), only to paint the background. */
function region(x, y) {
  if (y > 1) return 'single-inflection';
  if (x <= 1 && y >= cuspEdge(x)) return 'double-inflection';
  if (x <= 0 && y >= loopStartEdge(x)) return 'loop';
  if (x > 0 && x <= 1 && y >= loopEndEdge(x)) return 'loop';
  return 'arch';
}

let cachedChart = null;  // {width, height, canvas}

function chart(width, height) {
  if (cachedChart && cachedChart.width === width && cachedChart.height === height) return cachedChart.canvas;
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const ctx = canvas.getContext('2d');
  const image = ctx.createImageData(width, height);
  for (let py = 0; py < height; ++py) {
    for (let px = 0; px < width; ++px) {
      const x = kWindow.x0 + (px + 0.5) / width * (kWindow.x1 - kWindow.x0);
      const y = kWindow.y1 - (py + 0.5) / height * (kWindow.y1 - kWindow.y0);
      const [r, g, b] = kRegionColors[region(x, y)];
      const k = 4 * (py * width + px);
      image.data[k] = r;
      image.data[k + 1] = g;
      image.data[k + 2] = b;
      image.data[k + 3] = 255;
    }
  }
  ctx.putImageData(image, 0, 0);
  cachedChart = {width, height, canvas};
  return canvas;
}

/**
 * Draws the chart into `canvas` with one marker per entry of `marks`:
 * {label, color, point: [x, y] or null}. A point outside the window is drawn on its
 * border as a hollow marker.
 */
export function drawCanonicalMap(canvas, marks) {
  const ratio = Math.max(1, window.devicePixelRatio || 1);
  const width = canvas.clientWidth || 200;
  const height = canvas.clientHeight || 200;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.drawImage(chart(canvas.width, canvas.height), 0, 0);
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  const sx = (x) => (x - kWindow.x0) / (kWindow.x1 - kWindow.x0) * width;
  const sy = (y) => (kWindow.y1 - y) / (kWindow.y1 - kWindow.y0) * height;

  const edge = (f, a, b) => {
    ctx.beginPath();
    for (let k = 0; k <= 120; ++k) {
      const x = a + (b - a) * k / 120;
      if (k === 0) ctx.moveTo(sx(x), sy(f(x)));
      else ctx.lineTo(sx(x), sy(f(x)));
    }
    ctx.stroke();
  };
  ctx.lineWidth = 1.25;
  ctx.strokeStyle = '#b03a2e';
  edge(cuspEdge, kWindow.x0, 1);
  ctx.strokeStyle = '#6c3483';
  edge(loopStartEdge, 1.5 - Math.sqrt(11.25), 0);  // from y = -3 up to the origin
  edge(loopEndEdge, 0, 1);
  ctx.strokeStyle = '#1e8449';
  ctx.beginPath();
  ctx.moveTo(sx(kWindow.x0), sy(1));
  ctx.lineTo(sx(kWindow.x1), sy(1));
  ctx.stroke();
  ctx.strokeStyle = 'rgba(0,0,0,0.25)';
  ctx.beginPath();
  ctx.moveTo(sx(0), 0);
  ctx.lineTo(sx(0), height);
  ctx.moveTo(0, sy(0));
  ctx.lineTo(width, sy(0));
  ctx.stroke();

  ctx.font = '10px system-ui, sans-serif';
  ctx.fillStyle = '#3d4650';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.fillText('single inflection', sx(-3.3), sy(2.0));
  ctx.fillText('double inflection', sx(-3.3), sy(0.5));
  ctx.fillText('loop', sx(-1.8), sy(-1.4));
  ctx.fillText('arch', sx(0.8), sy(-1.8));
  // The edges by name, each in its line's colour beside the line (the short loop-at-t = 1
  // edge by a leader line from its name in the open arch region).
  ctx.font = 'italic 10px system-ui, sans-serif';
  ctx.fillStyle = '#b03a2e';
  ctx.textAlign = 'right';
  ctx.fillText('cusp', sx(-2.3) - 2, sy(cuspEdge(-2.3)) + 8);
  ctx.fillStyle = '#6c3483';
  ctx.textAlign = 'left';
  ctx.fillText('loop at t = 0', sx(-0.9) + 6, sy(loopStartEdge(-0.9)) + 4);
  const end = [sx(0.6), sy(loopEndEdge(0.6))];
  const text = 'loop at t = 1';
  const name = [Math.min(sx(1.15), width - 3 - ctx.measureText(text).width), sy(0.45)];
  ctx.strokeStyle = '#6c3483';
  ctx.lineWidth = 0.75;
  ctx.beginPath();
  ctx.moveTo(...end);
  ctx.lineTo(name[0] - 2, name[1] - 4);
  ctx.stroke();
  ctx.fillText(text, ...name);
  ctx.fillStyle = '#1e8449';
  ctx.fillText('inflection at t = 1', sx(-3.4), sy(1) - 7);
  canvas.dataset.edges = ['cusp', 'loop at t = 0', 'loop at t = 1', 'inflection at t = 1'].join('; ');
  ctx.font = '10px system-ui, sans-serif';
  ctx.fillStyle = '#3d4650';
  // The fixed images of P0, P1, P2.
  ctx.fillStyle = '#3d4650';
  for (const [x, y, name] of [[0, 0, 'P0'], [0, 1, 'P1'], [1, 1, 'P2']]) {
    ctx.beginPath();
    ctx.arc(sx(x), sy(y), 2.5, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillText(name, sx(x) + 4, sy(y) + (name === 'P0' ? 7 : -7));
  }
  marks.forEach((mark, k) => {
    if (!mark.point) return;
    const [x, y] = mark.point;
    const inside = x >= kWindow.x0 && x <= kWindow.x1 && y >= kWindow.y0 && y <= kWindow.y1;
    const px = Math.min(width - 5, Math.max(5, sx(x)));
    const py = Math.min(height - 5, Math.max(5, sy(y)));
    ctx.beginPath();
    ctx.arc(px, py, 5, 0, 2 * Math.PI);
    ctx.lineWidth = 2;
    ctx.strokeStyle = mark.color;
    ctx.fillStyle = inside ? mark.color : '#ffffff';
    ctx.fill();
    ctx.stroke();
    ctx.fillStyle = '#1b1f24';
    ctx.font = 'bold 11px system-ui, sans-serif';
    ctx.textAlign = px > width - 40 ? 'right' : 'left';
    ctx.fillText(`${mark.label}3`, px + (px > width - 40 ? -8 : 8), py + (k === 0 ? -8 : 8));
  });
}
