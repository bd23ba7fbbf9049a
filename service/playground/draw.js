// Draws the main canvas: control polygons and points (the page's state), and everything
// the service answered (sampled curves, the first polar, loops with their areas,
// overlaps, intersections, inflections and cusps). Nothing here computes geometry: the
// only arithmetic is the view's mapping to pixels.

export const kColors = Object.freeze({
  curves: ['#1f6fd1', '#d35400'],
  polar: '#8a3fd1',
  remove: '#c0392b',
  kinds: {transversal: '#c0392b', tangent: '#117a65', degenerate: '#5d6d7e'},
  overlap: 'rgba(241, 196, 15, 0.55)',
});

export const kPointNames = ['P', 'Q'];

function polyline(ctx, view, points) {
  ctx.beginPath();
  points.forEach((p, k) => {
    const [x, y] = view.toScreen(p);
    if (k === 0) ctx.moveTo(x, y);
    else ctx.lineTo(x, y);
  });
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

function label(ctx, view, p, text, color) {
  const [x, y] = view.toScreen(p);
  ctx.font = '12px system-ui, sans-serif';
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.lineWidth = 3;
  ctx.strokeStyle = 'rgba(255,255,255,0.85)';
  ctx.strokeText(text, x + 7, y - 4);
  ctx.fillStyle = color;
  ctx.fillText(text, x + 7, y - 4);
}

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

function drawLoops(ctx, view, state, answers, i) {
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
  ctx.restore();
  for (const {loop, points} of curve.loopPaths) {
    ctx.lineWidth = 1.5;
    dot(ctx, view, loop.point, 3.5, '#ffffff', color);  // the double point B(t1) = B(t2)
    label(ctx, view, centroid(points), areaText(loop.area), color);
  }
  if (closed && typeof curve.loopArea.closed_area === 'number') {
    const c = centroid(curve.evaluate.results.map((r) => r.point));
    label(ctx, view, c, `closed, signed ${areaText(curve.loopArea.closed_area)}`, color);
  }
}

/**
 * Draws everything. hover: {curve, index} of the control point under the cursor or
 * null; hoverMark: the index of the intersection under the cursor or -1.
 */
export function drawScene(view, state, answers, hover, hoverMark) {
  const ctx = view.context();
  const used = state.second ? [0, 1] : [0];
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  if (state.show.loops && answers) for (const i of used) drawLoops(ctx, view, state, answers, i);

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
  }

  const polar = answers?.polar;
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
      if (polar.control_points.length >= 2) {
        polyline(ctx, view, polar.control_points);
        ctx.stroke();
      }
      ctx.restore();
      dot(ctx, view, polar.curve_point, 5, '#ffffff', kColors.polar);
      if (state.show.labels) label(ctx, view, polar.curve_point, `B(${state.t0.toFixed(2)})`, kColors.polar);
    }
    if (state.show.polarPoints) {
      polar.control_points.forEach((p, k) => {
        ctx.save();
        const [x, y] = view.toScreen(p);
        ctx.fillStyle = kColors.polar;
        ctx.fillRect(x - 3.5, y - 3.5, 7, 7);
        ctx.restore();
        if (state.show.labels) label(ctx, view, p, `b${k}`, kColors.polar);
      });
    }
  }

  if (state.show.classify && answers) {
    for (const i of used) {
      for (const f of answers.curves[i].features) {
        const [x, y] = view.toScreen(f.point);
        ctx.save();
        ctx.strokeStyle = '#1b1f24';
        ctx.lineWidth = 1.5;
        ctx.beginPath();
        if (f.kind === 'cusp') {
          ctx.moveTo(x - 6, y - 6);
          ctx.lineTo(x + 6, y + 6);
          ctx.moveTo(x + 6, y - 6);
          ctx.lineTo(x - 6, y + 6);
        } else {
          ctx.moveTo(x - 6, y);
          ctx.lineTo(x + 6, y);
          ctx.moveTo(x, y - 6);
          ctx.lineTo(x, y + 6);
        }
        ctx.stroke();
        ctx.restore();
        if (state.show.labels) label(ctx, view, f.point, f.kind, '#1b1f24');
      }
    }
  }

  for (const i of used) {
    const points = state.curves[i].points;
    points.forEach((p, k) => {
      const hovered = hover && hover.curve === i && hover.index === k;
      if (state.show.points || hovered) {
        ctx.lineWidth = 2;
        dot(ctx, view, p, 5, i === state.active ? kColors.curves[i] : '#ffffff', kColors.curves[i]);
      }
      if (hovered && (state.mode === 'move' || state.mode === 'remove')) {
        const color = state.mode === 'remove' ? kColors.remove : kColors.curves[i];
        ctx.lineWidth = 3;
        dot(ctx, view, p, 11, null, color);
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
      for (const [key, list] of names) label(ctx, view, key.split(',').map(Number), list.join(' = '), kColors.curves[i]);
    }
  }

  if (state.show.intersections && answers?.intersections) {
    answers.intersections.intersections.forEach((hit, k) => {
      const [x, y] = view.toScreen(hit.point);
      drawKindMarker(ctx, x, y, hit.kind, 7, k === hoverMark);
    });
  }
}
