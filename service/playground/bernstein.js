// The Bernstein panel: the basis polynomials B_{i,n}(t) = C(n,i) t^i (1-t)^(n-i),
// i = 0..n, on [0, 1], each in the colour of its control point P_i, the one of the point
// under the cursor (or selected) emphasised, a line at t0 with each B_{i,n}(t0) marked,
// and a legend with those values: the weight of each control point in B(t0). These are
// the weights of the control points, not curve geometry, so they are computed here from
// the formula (the API has no basis-value route).

import {pointColor} from './draw.js';

/** Binomial coefficient C(n, k), exact for the degrees the service allows. */
export function binomial(n, k) {
  let c = 1;
  for (let j = 1; j <= k; ++j) c = c * (n - k + j) / j;
  return Math.round(c);
}

/** B_{i,n}(t). */
export function bernstein(n, i, t) {
  return binomial(n, i) * Math.pow(t, i) * Math.pow(1 - t, n - i);
}

/**
 * Draws the basis of degree n into `canvas` (sized to its CSS box).
 * highlight: the index to emphasise or -1; t0: marked.
 */
export function drawBernstein(canvas, n, highlight, t0) {
  const ratio = Math.max(1, window.devicePixelRatio || 1);
  const width = canvas.clientWidth || 300;
  const height = canvas.clientHeight || 150;
  if (canvas.width !== Math.round(width * ratio)) canvas.width = Math.round(width * ratio);
  if (canvas.height !== Math.round(height * ratio)) canvas.height = Math.round(height * ratio);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  const left = 26;
  const right = 8;
  const top = 8;
  const bottom = 18;
  const w = width - left - right;
  const h = height - top - bottom;
  const sx = (t) => left + t * w;
  const sy = (v) => top + (1 - v) * h;

  ctx.strokeStyle = '#b8bfc9';
  ctx.lineWidth = 1;
  ctx.strokeRect(left, top, w, h);
  ctx.fillStyle = '#5b6470';
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  ctx.fillText('1', left - 4, sy(1));
  ctx.fillText('0', left - 4, sy(0));
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  ctx.fillText('t = 0', sx(0) + 14, top + h + 3);
  ctx.fillText('1', sx(1), top + h + 3);
  if (!(n >= 1)) {
    ctx.textBaseline = 'middle';
    ctx.fillText('add two control points', left + w / 2, top + h / 2);
    return;
  }
  ctx.setLineDash([3, 3]);
  ctx.strokeStyle = '#8a3fd1';
  ctx.beginPath();
  ctx.moveTo(sx(t0), top);
  ctx.lineTo(sx(t0), top + h);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.fillStyle = '#8a3fd1';
  ctx.fillText(`t0 = ${t0.toFixed(2)}`, Math.min(Math.max(sx(t0), left + 24), left + w - 24), top + h + 3);

  const steps = Math.max(64, Math.round(w));
  const order = [...Array(n + 1).keys()].filter((i) => i !== highlight);
  if (highlight >= 0 && highlight <= n) order.push(highlight);  // drawn last, on top
  for (const i of order) {
    const on = i === highlight;
    ctx.strokeStyle = pointColor(i);
    ctx.globalAlpha = highlight >= 0 && !on ? 0.45 : 1;
    ctx.lineWidth = on ? 3.5 : 2;
    ctx.beginPath();
    for (let k = 0; k <= steps; ++k) {
      const t = k / steps;
      const x = sx(t);
      const y = sy(bernstein(n, i, t));
      if (k === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    }
    ctx.stroke();
    ctx.globalAlpha = 1;
    // B_{i,n}(t0) on the t0 line.
    ctx.beginPath();
    ctx.arc(sx(t0), sy(bernstein(n, i, t0)), on ? 5 : 4, 0, 2 * Math.PI);
    ctx.fillStyle = pointColor(i);
    ctx.fill();
    ctx.lineWidth = 1.5;
    ctx.strokeStyle = '#ffffff';
    ctx.stroke();
  }
  // Names at the peaks (B_{i,n} is largest at t = i/n), left out where they would crowd.
  const spacing = w / n;
  ctx.font = '11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  for (let i = 0; i <= n; ++i) {
    if (spacing < 34 && i !== highlight && !(i === 0 || i === n)) continue;
    const peak = i / n;
    ctx.fillStyle = pointColor(i);
    ctx.fillText(`B${i},${n}`, Math.min(Math.max(sx(peak), left + 16), left + w - 16),
                 Math.max(sy(bernstein(n, i, peak)) - 2, top + 12));
  }
}

/** The legend: per i its colour, B_{i,n}(t0), and P_i's weight in B(t0). */
export function renderBernsteinLegend(container, n, t0, points, pointName) {
  const items = [];
  if (n >= 1) {
    let sum = [0, 0];
    for (let i = 0; i <= n; ++i) {
      const b = bernstein(n, i, t0);
      sum = sum.map((v, k) => v + b * points[i][k]);
      const li = document.createElement('li');
      li.dataset.index = String(i);
      li.dataset.value = String(b);
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.backgroundColor = pointColor(i);
      const name = document.createElement('span');
      name.textContent = `B${i},${n}(t0) = `;
      const value = document.createElement('span');
      value.className = 'value';
      value.textContent = b.toFixed(4);
      li.append(swatch, name, value, ` · weight of ${pointName}${i}`);
      items.push(li);
    }
    const total = document.createElement('li');
    total.className = 'muted';
    total.textContent = `Σ B_i,n(t0) ${pointName}i = (${sum.map((v) => Number(v.toPrecision(6))).join(', ')}) = B(t0); the weights add up to 1`;
    items.push(total);
  }
  container.replaceChildren(...items);
}
