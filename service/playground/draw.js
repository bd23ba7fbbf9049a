// Draws the main canvas: control polygons and points (the page's state), and everything
// the service answered (sampled curves, the first polar, loops with their areas,
// overlaps, intersections, inflections and cusps, the edited curve's box with its
// extremes, its tangent, normal and osculating circle at t0, and the point nearest to
// the pointer), and de Casteljau's construction at t0 from the service's polars: level r
// holds b_i^r(t0), the control points of the r-th polar b(t0, ..., t0, t, ..., t), so
// level 1 is the first polar's control points and level n is B(t0). Nothing here
// computes geometry beyond the view's mapping to pixels and placing the osculating
// circle from the frame the service gave: centre B(t0) + N / kappa, radius 1 / |kappa|
// (N the unit normal, kappa the signed curvature). Labels go through a LabelLayout, so
// none covers another.

import {LabelLayout, subscript, superscript} from './labels.js';

export const kColors = Object.freeze({
  curves: ['#1f6fd1', '#d35400'],
  polar: '#8a3fd1',
  remove: '#c0392b',
  kinds: {transversal: '#c0392b', tangent: '#117a65', degenerate: '#5d6d7e'},
  overlap: 'rgba(241, 196, 15, 0.55)',
  box: '#546e7a',
  tangent: '#00838f',
  normal: '#8d6e63',
  osculating: '#00838f',
  nearest: '#d81b60',
  // One colour per control point P_i and its Bernstein polynomial B_{i,n}.
  points: ['#e6194b', '#3cb44b', '#4363d8', '#f58231', '#911eb4', '#42a5b5', '#f032e6', '#9a6324',
           '#00695c', '#800000', '#808000', '#000075'],
  // De Casteljau levels r = 1, 2, ...: level 1 in the polar's colour (it is the polar's polygon).
  levels: ['#8a3fd1', '#1e88e5', '#00897b', '#c49000', '#e65100', '#c62828', '#6d4c41', '#37474f'],
});

/** The mark of a cubic's feature at screen point (x, y): a diagonal cross for a cusp, an
 * upright one for an inflection (the canvas and the legend draw the same mark). */
export function drawFeatureMark(ctx, x, y, cusp) {
  ctx.save();
  ctx.strokeStyle = '#1b1f24';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  for (const [dx, dy] of cusp ? [[6, 6], [6, -6]] : [[6, 0], [0, 6]]) {
    ctx.moveTo(x - dx, y - dy);
    ctx.lineTo(x + dx, y + dy);
  }
  ctx.stroke();
  ctx.restore();
}

/** [r, g, b] of '#rrggbb'. */
const rgbOf = (hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));

/** [r, g, b] of hue h (degrees), saturation s and lightness l (percent). */
function rgbOfHsl(h, s, l) {
  const a = (s / 100) * Math.min(l / 100, 1 - l / 100);
  const f = (n) => {
    const k = (n + h / 30) % 12;
    return Math.round(255 * (l / 100 - a * Math.max(-1, Math.min(k - 3, 9 - k, 1))));
  };
  return [f(0), f(8), f(4)];
}

/** How different two colours look: RGB distance weighted by the mean red ("redmean"), a cheap
 * approximation of perceived difference. */
function colorDistance(a, b) {
  const r = (a[0] + b[0]) / 2;
  const [dr, dg, db] = a.map((v, k) => v - b[k]);
  return Math.sqrt((2 + r / 256) * dr * dr + 4 * dg * dg + (2 + (255 - r) / 256) * db * db);
}

// Past the twelve listed colours, each next one is the candidate (hues 6 degrees apart at
// three lightnesses dark enough to read on white) farthest from every colour before it:
// a greedy farthest-point choice, so no two control points share a colour at any degree.
const kCandidates = [];
for (let h = 0; h < 360; h += 6) for (const l of [28, 38, 48]) kCandidates.push(rgbOfHsl(h, 75, l));
const chosen = kColors.points.map(rgbOf);

/** The colour of control point i (and of B_{i,n}). */
export function pointColor(i) {
  while (chosen.length <= i) {
    let best = kCandidates[0];
    let farthest = -1;
    for (const c of kCandidates) {
      const d = Math.min(...chosen.map((p) => colorDistance(p, c)));
      if (d > farthest) {
        farthest = d;
        best = c;
      }
    }
    chosen.push(best);
  }
  return i < kColors.points.length ? kColors.points[i] : `rgb(${chosen[i].join(', ')})`;
}

/** The distance between the colours of points i and j (for tests: the palette's spread). */
export const pointColorDistance = (i, j) => (pointColor(Math.max(i, j)), colorDistance(chosen[i], chosen[j]));
/** The colour of de Casteljau level r >= 1. */
export const levelColor = (r) => kColors.levels[(r - 1) % kColors.levels.length];

/** Label ranks: lower is placed first and so never gives way to a higher one. */
const kRank = Object.freeze({point: 0, nearest: 1, curvePoint: 2, feature: 3, level: 4, area: 20});

export const kPointNames = ['P', 'Q'];

function polyline(ctx, view, points) {
  ctx.beginPath();
  points.forEach((p, k) => {
    const [x, y] = view.toScreen(p);
    if (k === 0) ctx.moveTo(x, y);
    else ctx.lineTo(x, y);
  });
}

/** The segments of a path (control points of degree 1 to 3, from /segments) as canvas
 * path commands, a closed subpath closed: the canvas draws each Bézier segment itself. */
export function tracePath(ctx, view, path) {
  ctx.beginPath();
  for (const subpath of path.subpaths) {
    const first = subpath.first_segment;
    if (subpath.segment_count === 0) continue;
    ctx.moveTo(...view.toScreen(path.segments[first][0]));
    for (let k = first; k < first + subpath.segment_count; ++k) {
      const q = path.segments[k].slice(1).flatMap((p) => view.toScreen(p));
      if (q.length === 2) ctx.lineTo(...q);
      else if (q.length === 4) ctx.quadraticCurveTo(...q);
      else ctx.bezierCurveTo(...q);
    }
    if (subpath.closed) ctx.closePath();
  }
}

function dot(ctx, view, p, radius, fill, stroke) {
  const [x, y] = view.toScreen(p);
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  if (fill) {
    ctx.fillStyle = fill;
    ctx.fill();
  }
  if (stroke) {
    ctx.strokeStyle = stroke;
    ctx.stroke();
  }
}

/** Keeps a mark's disc at world point p clear of labels. */
function keepClear(labels, view, p, radius) {
  const [x, y] = view.toScreen(p);
  labels.keepClear(x, y, radius);
}

function label(labels, view, p, text, color, rank) {
  const [x, y] = view.toScreen(p);
  labels.add(x, y, text, color, rank, rank >= kRank.area);
}

/** The name b_i^r of a de Casteljau point. */
export const levelName = (i, r) => `b${subscript(i)}${superscript(r)}`;

/** Marker shape per intersection kind, so kinds differ without color too. */
export function drawKindMarker(ctx, x, y, kind, size, highlighted) {
  ctx.beginPath();
  if (kind === 'tangent') {
    ctx.moveTo(x, y - size);
    ctx.lineTo(x + size, y);
    ctx.lineTo(x, y + size);
    ctx.lineTo(x - size, y);
    ctx.closePath();
  } else if (kind === 'degenerate') {
    ctx.rect(x - size * 0.8, y - size * 0.8, size * 1.6, size * 1.6);
  } else {
    ctx.arc(x, y, size * 0.85, 0, 2 * Math.PI);
  }
  ctx.fillStyle = highlighted ? '#ffffff' : (kColors.kinds[kind] ?? kColors.kinds.degenerate);
  ctx.strokeStyle = highlighted ? (kColors.kinds[kind] ?? '#000') : '#ffffff';
  ctx.lineWidth = 2;
  ctx.fill();
  ctx.stroke();
}

function centroid(points) {
  let x = 0;
  let y = 0;
  for (const p of points) {
    x += p[0];
    y += p[1];
  }
  return [x / points.length, y / points.length];
}

function areaText(value) {
  return `area ${formatNumber(value)}`;
}

/** A number for display: at most 6 significant digits, no trailing zeros. */
export function formatNumber(v) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return String(v);
  if (v !== 0 && (Math.abs(v) >= 1e6 || Math.abs(v) < 1e-4)) return v.toExponential(4);
  return String(Number(v.toPrecision(6)));
}

function drawLoops(ctx, view, labels, state, answers, i) {
  const color = kColors.curves[i];
  const curve = answers.curves[i];
  ctx.save();
  ctx.globalAlpha = 0.22;
  ctx.fillStyle = color;
  for (const {points} of curve.loopPaths) {
    polyline(ctx, view, points);
    ctx.closePath();
    ctx.fill();
  }
  const closed = curve.loopArea?.closed && curve.evaluate;
  if (closed) {
    polyline(ctx, view, curve.evaluate.results.map((r) => r.point));
    ctx.closePath();
    ctx.fill('evenodd');
  }
  const closedPath = curve.path && typeof curve.loopArea?.closed_area === 'number';
  if (closedPath) {
    tracePath(ctx, view, curve.path);
    ctx.fill('nonzero');
  }
  ctx.restore();
  if (closedPath) {
    const box = answers.measure?.curve === i && answers.measure.bounds;
    const c = box ? [(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2] : curve.path.segments[0][0];
    label(labels, view, c, `encloses signed ${areaText(curve.loopArea.closed_area)}`, color, kRank.area);
  }
  for (const {loop, points} of curve.loopPaths) {
    ctx.lineWidth = 1.5;
    dot(ctx, view, loop.point, 3.5, '#ffffff', color);  // the double point B(t1) = B(t2)
    // At the loop's centre, or beside its boundary when the centre is taken (by the osculating circle, say).
    const anchors = [centroid(points), ...points.filter((p, k) => k % 12 === 6)].map((p) => view.toScreen(p));
    labels.addAnywhere(anchors, areaText(loop.area), color, kRank.area, true);
  }
  if (closed && typeof curve.loopArea.closed_area === 'number') {
    const c = centroid(curve.evaluate.results.map((r) => r.point));
    label(labels, view, c, `closed, signed ${areaText(curve.loopArea.closed_area)}`, color, kRank.area);
  }
}

/** The osculating circle at a frame answer, or null where the curvature is 0 or undefined. */
export function osculatingCircle(frame) {
  if (!frame || typeof frame.curvature !== 'number' || frame.curvature === 0 || !frame.normal) return null;
  const k = frame.curvature;
  return {centre: [frame.point[0] + frame.normal[0] / k, frame.point[1] + frame.normal[1] / k], radius: 1 / Math.abs(k)};
}

function arrow(ctx, view, from, direction, length, color) {
  const [x, y] = view.toScreen(from);
  const dx = direction[0] * length;
  const dy = -direction[1] * length;  // the world's y points up
  ctx.save();
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x, y);
  ctx.lineTo(x + dx, y + dy);
  ctx.stroke();
  const angle = Math.atan2(dy, dx);
  ctx.beginPath();
  ctx.moveTo(x + dx, y + dy);
  ctx.lineTo(x + dx - 9 * Math.cos(angle - 0.4), y + dy - 9 * Math.sin(angle - 0.4));
  ctx.lineTo(x + dx - 9 * Math.cos(angle + 0.4), y + dy - 9 * Math.sin(angle + 0.4));
  ctx.closePath();
  ctx.fill();
  ctx.restore();
}

/** The box of the edited curve (/bounds) and the curve's points at its critical parameters. */
function drawBox(ctx, view, state, measure) {
  const box = measure.bounds;
  const [x0, y0] = view.toScreen(box.min);
  const [x1, y1] = view.toScreen(box.max);
  ctx.save();
  ctx.strokeStyle = kColors.box;
  ctx.lineWidth = 1;
  ctx.setLineDash([6, 3]);
  ctx.strokeRect(x0, y1, x1 - x0, y0 - y1);
  ctx.setLineDash([]);
  for (const e of measure.extremes) {
    const [x, y] = view.toScreen(e.point);
    ctx.beginPath();
    ctx.moveTo(x, y - 5);
    ctx.lineTo(x + 5, y);
    ctx.lineTo(x, y + 5);
    ctx.lineTo(x - 5, y);
    ctx.closePath();
    ctx.fillStyle = '#ffffff';
    ctx.fill();
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }
  ctx.restore();
}

/** Tangent and normal arrows at B(t0) and the osculating circle there. */
function drawFrame(ctx, view, labels, frame) {
  if (!frame.tangent) return;  // a cusp: no direction
  const circle = osculatingCircle(frame);
  if (circle) {
    const [cx, cy] = view.toScreen(circle.centre);
    const r = circle.radius * view.scale;
    if (r < 1e5) {
      labels.keepOffRing(cx, cy, r);
      ctx.save();
      ctx.strokeStyle = kColors.osculating;
      ctx.globalAlpha = 0.8;
      ctx.lineWidth = 1.25;
      ctx.beginPath();
      ctx.arc(cx, cy, r, 0, 2 * Math.PI);
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(cx, cy, 2.5, 0, 2 * Math.PI);
      ctx.fillStyle = kColors.osculating;
      ctx.fill();
      ctx.restore();
    }
  }
  arrow(ctx, view, frame.point, frame.tangent, 56, kColors.tangent);
  arrow(ctx, view, frame.point, frame.normal, 36, kColors.normal);
}

/** The segment from the pointer to the nearest point of the edited curve, with the distance. */
function drawNearest(ctx, view, labels, state, nearest) {
  const {target, answer} = nearest;
  const [tx, ty] = view.toScreen(target);
  const [px, py] = view.toScreen(answer.point);
  ctx.save();
  ctx.strokeStyle = kColors.nearest;
  ctx.lineWidth = 1.5;
  ctx.setLineDash([4, 3]);
  ctx.beginPath();
  ctx.moveTo(tx, ty);
  ctx.lineTo(px, py);
  ctx.stroke();
  ctx.restore();
  dot(ctx, view, answer.point, 4.5, kColors.nearest, '#ffffff');
  if (state.show.labels) {
    label(labels, view, [(target[0] + answer.point[0]) / 2, (target[1] + answer.point[1]) / 2],
          `d = ${formatNumber(answer.distance)}`, kColors.nearest, kRank.nearest);
  }
}

/** Labels closer together than this (CSS pixels, about a label's width) would stand in a row
 * that hides the drawing: a level whose neighbouring points are closer keeps its marks and
 * colour but not its names (the legend says what each level is). */
const kLabelSpacing = 26;

/** Whether the points of one level are far enough apart (on average) to be labelled one by one. */
function roomForLabels(view, points) {
  if (points.length < 2) return true;
  let total = 0;
  for (let k = 1; k < points.length; ++k) {
    const [x0, y0] = view.toScreen(points[k - 1]);
    const [x1, y1] = view.toScreen(points[k]);
    total += Math.hypot(x1 - x0, y1 - y0);
  }
  return total / (points.length - 1) >= kLabelSpacing;
}

/** De Casteljau's levels 1..n at t0: each level's polygon and points, labelled b_i^r. */
function drawConstruction(ctx, view, labels, state, levels) {
  const n = levels.length - 1;
  for (let r = 1; r < n; ++r) {
    ctx.save();
    ctx.strokeStyle = levelColor(r);
    ctx.lineWidth = 1.5;
    polyline(ctx, view, levels[r]);
    ctx.stroke();
    ctx.restore();
  }
  for (let r = 2; r < n; ++r) {
    const named = roomForLabels(view, levels[r]);
    levels[r].forEach((p, i) => {
      ctx.lineWidth = 1.25;
      dot(ctx, view, p, 4, levelColor(r), '#ffffff');
      keepClear(labels, view, p, 4);
      if (!state.show.labels) return;
      if (named) label(labels, view, p, levelName(i, r), levelColor(r), kRank.level + r);
      else labels.omit(levelName(i, r));
    });
  }
}

/** Level-1 points: the first polar's control points b_i^1, drawn as squares. */
function drawPolarPoints(ctx, view, labels, state, points) {
  const named = roomForLabels(view, points);
  points.forEach((p, i) => {
    const [x, y] = view.toScreen(p);
    ctx.fillStyle = kColors.polar;
    ctx.strokeStyle = '#ffffff';
    ctx.lineWidth = 1;
    ctx.fillRect(x - 4, y - 4, 8, 8);
    ctx.strokeRect(x - 4, y - 4, 8, 8);
    labels.keepClear(x, y, 4);
    if (!state.show.labels) return;
    if (named) label(labels, view, p, levelName(i, 1), kColors.polar, kRank.level + 1);
    else labels.omit(levelName(i, 1));
  });
}

/**
 * Draws everything and returns the label layout (the labels' boxes, for tests).
 * hover: {curve, index} of the control point under the cursor or null; hoverMark: the
 * index of the intersection under the cursor or -1; nearest: {target, answer} or null.
 */
export function drawScene(view, state, answers, hover, hoverMark, nearest = null) {
  const ctx = view.context();
  const labels = new LabelLayout(view.cssWidth, view.cssHeight);
  const used = state.second ? [0, 1] : [0];
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  if (state.show.loops && answers) for (const i of used) drawLoops(ctx, view, labels, state, answers, i);

  if (state.show.intersections && answers) {
    ctx.save();
    ctx.strokeStyle = kColors.overlap;
    ctx.lineWidth = 12;
    for (const i of used) {
      for (const points of answers.curves[i].overlapPaths) {
        polyline(ctx, view, points);
        ctx.stroke();
      }
    }
    ctx.restore();
  }

  const measure = answers?.measure;
  const measured = measure && used.includes(measure.curve);
  if (measured && state.show.box && measure.bounds) drawBox(ctx, view, state, measure);

  for (const i of used) {
    const points = state.curves[i].points;
    if (state.show.polygon && points.length >= 2) {
      ctx.save();
      ctx.setLineDash([5, 4]);
      ctx.strokeStyle = '#7b8794';
      ctx.lineWidth = 1;
      polyline(ctx, view, points);
      ctx.stroke();
      ctx.restore();
    }
    const evaluated = answers?.curves[i].evaluate;
    if (state.show.curve && evaluated) {
      ctx.strokeStyle = kColors.curves[i];
      ctx.lineWidth = i === state.active ? 3 : 2.25;
      polyline(ctx, view, evaluated.results.map((r) => r.point));
      ctx.stroke();
    }
    const path = answers?.curves[i].path;
    if (state.show.curve && path && state.curves[i].path) {
      ctx.strokeStyle = kColors.curves[i];
      ctx.lineWidth = i === state.active ? 3 : 2.25;
      tracePath(ctx, view, path);
      ctx.stroke();
    }
  }

  const polar = answers?.polar;
  const levels = answers?.casteljau;
  if (state.show.casteljau && levels && used.includes(levels.curve)) drawConstruction(ctx, view, labels, state, levels.levels);
  if (polar && used.includes(polar.curve)) {
    if (state.show.polar) {
      ctx.save();
      ctx.strokeStyle = kColors.polar;
      ctx.lineWidth = 2;
      if (polar.results.length >= 2) {
        polyline(ctx, view, polar.results.map((r) => r.point));
        ctx.stroke();
      }
      ctx.setLineDash([3, 4]);
      ctx.lineWidth = 1;
      if (polar.control_points.length >= 2 && !state.show.casteljau) {
        polyline(ctx, view, polar.control_points);
        ctx.stroke();
      }
      ctx.restore();
    }
    if ((state.show.polarPoints || state.show.casteljau) && polar.control_points.length >= 2) {
      drawPolarPoints(ctx, view, labels, state, polar.control_points);
    }
  }
  if (measured && state.show.frame && measure.frame) drawFrame(ctx, view, labels, measure.frame);
  if (polar && used.includes(polar.curve) && (state.show.polar || state.show.casteljau)) {
    ctx.lineWidth = 2;
    dot(ctx, view, polar.curve_point, 5, '#ffffff', kColors.polar);
    keepClear(labels, view, polar.curve_point, 5);
    if (state.show.labels) label(labels, view, polar.curve_point, `B(${state.t0.toFixed(2)})`, kColors.polar, kRank.curvePoint);
  }

  if (state.show.classify && answers) {
    for (const i of used) {
      for (const f of answers.curves[i].features) {
        const [x, y] = view.toScreen(f.point);
        drawFeatureMark(ctx, x, y, f.kind === 'cusp');
        if (state.show.labels) label(labels, view, f.point, f.kind, '#1b1f24', kRank.feature);
      }
    }
  }

  for (const i of used) {
    const points = state.curves[i].points;
    points.forEach((p, k) => {
      const hovered = hover && hover.curve === i && hover.index === k;
      const selected = state.selected && state.selected.curve === i && state.selected.index === k;
      if (state.show.points || hovered || selected) {
        ctx.lineWidth = 2;
        dot(ctx, view, p, 5.5, i === state.active ? pointColor(k) : '#ffffff', kColors.curves[i]);
        keepClear(labels, view, p, 6);
      }
      if (selected) {
        ctx.save();
        ctx.setLineDash([3, 3]);
        ctx.lineWidth = 1.5;
        dot(ctx, view, p, 10, null, '#1b1f24');
        ctx.restore();
      }
      if (hovered && (state.mode === 'move' || state.mode === 'remove')) {
        const color = state.mode === 'remove' ? kColors.remove : kColors.curves[i];
        ctx.lineWidth = 3;
        dot(ctx, view, p, 12, null, color);
        if (state.mode === 'remove') {
          const [x, y] = view.toScreen(p);
          ctx.beginPath();
          ctx.moveTo(x - 5, y - 5);
          ctx.lineTo(x + 5, y + 5);
          ctx.moveTo(x + 5, y - 5);
          ctx.lineTo(x - 5, y + 5);
          ctx.strokeStyle = color;
          ctx.stroke();
        }
      }
    });
    if (state.show.labels) {
      // Coincident points share one label ("P0 = P4" on a closed curve).
      const names = new Map();
      points.forEach((p, k) => {
        const key = `${p[0]},${p[1]}`;
        names.set(key, [...(names.get(key) ?? []), `${kPointNames[i]}${k}`]);
      });
      for (const [key, list] of names) {
        label(labels, view, key.split(',').map(Number), list.join(' = '), kColors.curves[i], kRank.point);
      }
    }
  }

  if (state.show.loops && answers) {
    // A path's self-intersections (/intersections of the path alone).
    for (const i of used) {
      for (const hit of answers.curves[i].selfIntersections?.intersections ?? []) {
        const [x, y] = view.toScreen(hit.point);
        drawKindMarker(ctx, x, y, hit.kind, 5, false);
      }
    }
  }
  if (state.show.intersections && answers?.intersections) {
    answers.intersections.intersections.forEach((hit, k) => {
      const [x, y] = view.toScreen(hit.point);
      drawKindMarker(ctx, x, y, hit.kind, 7, k === hoverMark);
    });
  }
  if (state.show.nearest && nearest) drawNearest(ctx, view, labels, state, nearest);
  labels.draw(ctx);
  return labels;
}
