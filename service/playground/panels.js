// The side panel's text: values (B(t0), the polar's control points, the control points),
// the cubic types, the intersections and loops, and the API's errors. Built from the
// answers of the last round; numbers shown rounded, the full answers are on
// window.playground for whoever needs every digit.

import {kColors, kPointNames, formatNumber, levelName, osculatingCircle} from './draw.js';

const fmt = formatNumber;
const pt = (p) => `(${fmt(p[0])}, ${fmt(p[1])})`;

function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) {
    if (k === 'class') node.className = v;
    else if (k === 'style') node.style.cssText = v;
    else node.setAttribute(k, v);
  }
  for (const c of children) node.append(c);
  return node;
}

function replace(container, nodes) {
  container.replaceChildren(...nodes);
}

export function renderValues(container, state, answers, nearest) {
  const rows = [];
  const add = (term, value, id) => {
    rows.push(el('dt', {}, term));
    rows.push(el('dd', id ? {id} : {}, value));
  };
  const active = state.active;
  const curve = state.curves[active];
  const name = kPointNames[active];
  const path = answers?.curves[active]?.path;
  add('Editing', curve.path ? `curve ${curve.name}, an SVG path${path ? ` of ${path.segments.length} segments in ${path.subpaths.length} subpath${path.subpaths.length > 1 ? 's' : ''}` : ''} (path mode)`
                            : `curve ${curve.name}, ${curve.points.length} control point${curve.points.length === 1 ? '' : 's'}` +
                              (curve.points.length >= 2 ? `, degree ${curve.points.length - 1}` : ''), 'value-degree');
  if (curve.path) {
    const m = answers?.measure && answers.measure.curve === active ? answers.measure : null;
    const loops = answers?.curves[active]?.loopArea;
    const self = answers?.curves[active]?.selfIntersections;
    add('Length', m?.length ? fmt(m.length.length) : '—', 'value-length');
    add('Box', m?.bounds ? `${pt(m.bounds.min)} to ${pt(m.bounds.max)}` : '—', 'value-box');
    add('Enclosed area', typeof loops?.closed_area === 'number' ? `${fmt(loops.closed_area)} (signed, counter-clockwise positive)`
                                                                : (loops ? 'none (no closed subpath)' : '—'), 'value-area');
    add('Loops', loops ? `${loops.loops.length}${loops.loops.length ? `, total area ${fmt(loops.area)}` : ''}` : '—', 'value-loops');
    add('Self-intersections', self ? String(self.intersections.length) : '—', 'value-self');
    add('Nearest to pointer', nearest ? `${pt(nearest.answer.point)} on segment ${nearest.answer.segment} at t = ${fmt(nearest.answer.t)}, ` +
                                        `distance ${fmt(nearest.answer.distance)}` : 'point at the drawing', 'value-nearest');
    replace(container, rows);
    return;
  }
  add('t0', state.t0.toFixed(2), 'value-t0');
  const polar = answers?.polar && answers.polar.curve === active ? answers.polar : null;
  add(`B(t0)`, polar ? pt(polar.curve_point) : '—', 'value-curve-point');
  add('Polar points', polar ? polar.control_points.map((p, k) => `${levelName(k, 1)} ${pt(p)}`).join(', ') : '—',
      'value-polar-points');
  add('Control points', curve.points.length ? curve.points.map((p, k) => `${name}${k} ${pt(p)}`).join(', ') : '—',
      'value-control-points');
  const m = answers?.measure && answers.measure.curve === active ? answers.measure : null;
  add('Length', m?.length ? fmt(m.length.length) : '—', 'value-length');
  add('Length of [0, t0]', m?.lengthToT0 ? fmt(m.lengthToT0.length) : '—', 'value-length-t0');
  add('Box', m?.bounds ? `${pt(m.bounds.min)} to ${pt(m.bounds.max)}` : '—', 'value-box');
  const f = m?.frame;
  add('Tangent at t0', f ? (f.tangent ? pt(f.tangent) : 'none (B′(t0) = 0: a cusp)') : '—', 'value-tangent');
  add('Normal at t0', f?.normal ? pt(f.normal) : '—', 'value-normal');
  add('Curvature at t0', f ? (typeof f.curvature === 'number' ? fmt(f.curvature) : 'undefined') : '—', 'value-curvature');
  const circle = osculatingCircle(f);
  add('Osculating circle', circle ? `radius ${fmt(circle.radius)}, centre ${pt(circle.centre)}`
                                  : (f?.curvature === 0 ? 'none (curvature 0: radius ∞)' : '—'), 'value-osculating');
  add('Nearest to pointer', nearest ? `${pt(nearest.answer.point)} at t = ${fmt(nearest.answer.t)}, distance ${fmt(nearest.answer.distance)}`
                                    : 'point at the drawing', 'value-nearest');
  replace(container, rows);
}

export function renderTypes(container, state, answers) {
  const items = [];
  for (const i of state.second ? [0, 1] : [0]) {
    const c = state.curves[i];
    const answer = answers?.curves[i]?.classify;
    const li = el('li', {'data-curve': c.name});
    li.append(el('strong', {style: `color:${kColors.curves[i]}`}, `${c.name}: `));
    if (c.points.length !== 4) {
      li.append(el('span', {class: 'muted'}, 'types are for cubics (4 control points)'));
    } else if (!answer) {
      li.append(el('span', {class: 'muted'}, 'no answer (see the error above)'));
    } else {
      li.append(el('span', {class: 'type'}, answer.type));
      const parts = [];
      parts.push(answer.canonical_point ? `canonical ${kPointNames[i]}3 ${pt(answer.canonical_point)}`
                                        : 'no canonical point (P0, P1, P2 collinear)');
      if (answer.inflections?.length) parts.push(`inflections t = ${answer.inflections.map(fmt).join(', ')}`);
      if (typeof answer.cusp === 'number') parts.push(`cusp t = ${fmt(answer.cusp)}`);
      if (answer.self_intersection) {
        parts.push(`double point t = ${answer.self_intersection.t.map(fmt).join(', ')} at ${pt(answer.self_intersection.point)}`);
      }
      if (answer.loop_blinn) parts.push(`Loop–Blinn class of the unbounded cubic: ${answer.loop_blinn}`);
      li.append(el('div', {class: 'small'}, parts.join('; ')));
    }
    items.push(li);
  }
  replace(container, items);
}

/** "A segment i × B segment j: " when a curve is a path (t is local to segment i, s to j), else "". */
export function segmentsText(state, hit) {
  if (!hit.segments || !(state.curves[0].path || state.curves[1].path)) return '';
  return `A segment ${hit.segments[0]} × B segment ${hit.segments[1]}: `;
}

/** Whether the service can take the curve: a path, or at least two control points. */
const drawable = (curve) => Boolean(curve.path) || curve.points.length >= 2;

export function renderIntersections(container, state, answers) {
  if (!state.second) {
    replace(container, [el('li', {class: 'muted'}, 'Turn on "Second curve (B)" and add its points.')]);
    return;
  }
  const x = answers?.intersections;
  if (!x) {
    const waiting = !drawable(state.curves[0]) || !drawable(state.curves[1]);
    replace(container, [el('li', {class: 'muted'}, waiting ? 'Both curves need two control points (or a path).' : 'no answer (see the error above)')]);
    return;
  }
  const items = x.intersections.map((hit, k) => el('li', {'data-index': String(k), 'data-kind': hit.kind},
      el('span', {class: `kind kind-${hit.kind}`}, hit.kind),
      `${segmentsText(state, hit)}t = ${fmt(hit.t)}, s = ${fmt(hit.s)} at ${pt(hit.point)}`));
  for (const o of x.overlaps ?? []) {
    items.push(el('li', {'data-kind': 'overlap'}, el('span', {class: 'kind kind-overlap'}, 'overlap'),
        `${segmentsText(state, o)}t ∈ [${o.t_interval.map(fmt).join(', ')}], s ∈ [${o.s_interval.map(fmt).join(', ')}]`));
  }
  if (items.length === 0) items.push(el('li', {class: 'muted'}, 'none: the curves do not meet'));
  if (x.stats) {
    // How the search went (method, iterations, boxes): for the curious, folded away.
    const s = Object.entries(x.stats).map(([k, v]) => `${k} ${typeof v === 'number' ? fmt(v) : v}`).join(', ');
    const details = el('details', {class: 'stats'}, el('summary', {}, 'Search statistics'), el('div', {class: 'small'}, s));
    details.open = Boolean(container.querySelector('details.stats')?.open);
    items.push(el('li', {class: 'muted small'}, details));
  }
  replace(container, items);
}

export function renderLoops(container, state, answers) {
  const items = [];
  let unanswered = 0;
  for (const i of state.second ? [0, 1] : [0]) {
    const c = state.curves[i];
    const a = answers?.curves[i]?.loopArea;
    if (!a) {
      if (c.points.length >= 3) ++unanswered;
      continue;
    }
    for (const loop of a.loops) {
      const where = loop.segments ? `from segment ${loop.segments[0]} at t = ${fmt(loop.t[0])} to segment ${loop.segments[1]} at ` +
                                    `t = ${fmt(loop.t[1])}` : `t ∈ [${loop.t.map(fmt).join(', ')}]`;
      items.push(el('li', {'data-curve': c.name},
          el('strong', {style: `color:${kColors.curves[i]}`}, `${c.name}: `),
          `${loop.kind && loop.kind !== 'transversal' ? `${loop.kind} ` : ''}loop ${where} ` +
          `at ${pt(loop.point)}, area ${fmt(loop.area)} (signed ${fmt(loop.signed_area)})`));
    }
    for (const hit of answers.curves[i].selfIntersections?.intersections ?? []) {
      items.push(el('li', {'data-curve': c.name, 'data-kind': 'self'},
          el('strong', {style: `color:${kColors.curves[i]}`}, `${c.name}: `),
          `crosses itself (${hit.kind}): segment ${hit.segments[0]} at t = ${fmt(hit.t)} and segment ${hit.segments[1]} ` +
          `at s = ${fmt(hit.s)}, at ${pt(hit.point)}`));
    }
    for (const o of a.overlaps ?? []) {
      items.push(el('li', {'data-curve': c.name, 'data-kind': 'overlap'},
          el('strong', {style: `color:${kColors.curves[i]}`}, `${c.name}: `),
          `retraces itself: t ∈ [${o.t_interval.map(fmt).join(', ')}] and [${o.s_interval.map(fmt).join(', ')}]`));
    }
    if (a.closed && typeof a.closed_area === 'number') {
      items.push(el('li', {'data-curve': c.name, 'data-kind': 'closed'}, el('strong', {style: `color:${kColors.curves[i]}`}, `${c.name}: `),
          `closed curve, signed area ${fmt(a.closed_area)}`));
    }
    if (a.loops.length > 1) items.push(el('li', {class: 'small'}, `${c.name}: total loop area ${fmt(a.area)}`));
  }
  if (unanswered) items.push(el('li', {class: 'muted'}, 'no answer (see the error above)'));
  else if (items.length === 0) items.push(el('li', {class: 'muted'}, 'no self-intersection loops'));
  replace(container, items);
}

/** Where an error belongs: beside the control-point table when the service pointed at points. */
function placeOf(problem) {
  const pointers = (problem?.errors ?? []).map((e) => e.pointer ?? '');
  return pointers.some((p) => /^\/(points|curves)(\/|$)/.test(p)) ? 'points' : 'general';
}

/**
 * The failed requests' problems, each once (requests refused for the same reason are
 * listed together), beside the control that caused them: places.points for problems
 * the service pointed into the control points, places.general for the rest.
 */
export function renderErrors(places, errors) {
  const groups = new Map();  // key -> {error, whats, place}
  for (const {what, error} of errors) {
    const p = error.problem ?? {};
    const key = `${error.status}|${p.title ?? ''}|${p.detail ?? ''}`;
    if (!groups.has(key)) groups.set(key, {error, whats: [], place: placeOf(p)});
    groups.get(key).whats.push(what);
  }
  const items = {points: [], general: []};
  for (const {error, whats, place} of groups.values()) {
    const p = error.problem ?? {};
    const li = el('li', {'data-route': error.route, 'data-status': String(error.status)});
    li.append(el('strong', {}, `POST ${error.route} → ${error.status || 'no answer'} ${p.title ?? ''}`));
    if (p.detail) li.append(el('div', {}, p.detail));
    if (Array.isArray(p.errors) && p.errors.length) {
      li.append(el('ul', {}, ...p.errors.map((e) => el('li', {}, el('code', {}, e.pointer || '/'), ` ${e.message}`))));
    }
    li.append(el('div', {class: 'small'}, `Asked for: ${whats.join(', ')}.`));
    if (error.status === 401) li.append(el('div', {class: 'small'}, 'Enter the token under "API token" in the panel.'));
    items[place].push(li);
  }
  replace(places.points, items.points);
  replace(places.general, items.general);
}
