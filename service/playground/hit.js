// What is under the cursor: a control point of a curve being shown (the curve being
// edited first), or an intersection mark from the last /intersections answer.

import {usedCurves} from './compute.js';

/** The control point within `radius` CSS pixels of (sx, sy), the active curve first. */
export function pointAt(state, view, sx, sy, radius) {
  let best = null;
  let bestDistance = radius;
  const order = [state.active, ...usedCurves(state).filter((i) => i !== state.active)];
  for (const i of order) {
    if (!usedCurves(state).includes(i)) continue;
    state.curves[i].points.forEach((p, k) => {
      const [x, y] = view.toScreen(p);
      const d = Math.hypot(x - sx, y - sy);
      if (d < bestDistance - 1e-9) {
        best = {curve: i, index: k};
        bestDistance = d;
      }
    });
  }
  return best;
}

/** The index of the intersection mark within `radius` CSS pixels of (sx, sy), or -1. */
export function markAt(state, view, answers, sx, sy, radius) {
  const hits = (state.show.intersections && answers?.intersections?.intersections) || [];
  let best = -1;
  let bestDistance = radius;
  hits.forEach((hit, k) => {
    const [x, y] = view.toScreen(hit.point);
    const d = Math.hypot(x - sx, y - sy);
    if (d < bestDistance) {
      best = k;
      bestDistance = d;
    }
  });
  return best;
}
