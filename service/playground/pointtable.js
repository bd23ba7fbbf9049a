// The control points of the curve being edited as a table of text fields: a typed
// number takes effect on Enter or when the field is left (anything else is refused with
// a message), each row has its colour (that of its Bernstein weight) and a button to
// remove the point. The rows are rebuilt only when their count
// changes, so the field being typed in keeps its focus while answers arrive.

import {kPointNames, pointColor} from './draw.js';

/**
 * Shows `points` of curve `curve` in `tbody`. onEdit(index, axis, value) gets a finite
 * number; onInvalid(index, axis, text) a field that is not one; onRemove(index) and
 * onSelect(index) the row's button and focus.
 */
export function renderPointTable(tbody, curve, points, selected, handlers) {
  const name = kPointNames[curve];
  if (tbody.rows.length !== points.length || tbody.dataset.curve !== String(curve)) {
    tbody.dataset.curve = String(curve);
    tbody.replaceChildren(...points.map((_, k) => row(name, k, handlers)));
  }
  points.forEach((p, k) => {
    const tr = tbody.rows[k];
    tr.classList.toggle('selected', selected !== null && selected.curve === curve && selected.index === k);
    for (const axis of [0, 1]) {
      const input = tr.querySelector(`input[data-axis="${axis}"]`);
      if (document.activeElement !== input && input.value !== String(p[axis])) input.value = String(p[axis]);
      input.classList.remove('invalid');
    }
  });
}

function row(name, k, handlers) {
  const tr = document.createElement('tr');
  tr.dataset.index = String(k);
  const th = document.createElement('th');
  th.scope = 'row';
  const swatch = document.createElement('span');
  swatch.className = 'swatch';
  swatch.style.backgroundColor = pointColor(k);
  th.append(swatch, `${name}${k}`);
  tr.append(th);
  for (const axis of [0, 1]) {
    const td = document.createElement('td');
    const input = document.createElement('input');
    input.type = 'text';
    input.inputMode = 'decimal';
    input.dataset.axis = String(axis);
    input.setAttribute('aria-label', `${name}${k} ${axis === 0 ? 'x' : 'y'}`);
    input.addEventListener('change', () => {
      const text = input.value.trim();
      const value = Number(text);
      if (text === '' || !Number.isFinite(value)) {
        input.classList.add('invalid');
        handlers.onInvalid(k, axis, input.value);
      } else {
        handlers.onEdit(k, axis, value);
      }
    });
    input.addEventListener('focus', () => handlers.onSelect(k));
    td.append(input);
    tr.append(td);
  }
  const td = document.createElement('td');
  const remove = document.createElement('button');
  remove.type = 'button';
  remove.className = 'remove-point';
  remove.textContent = '×';
  remove.title = `Remove ${name}${k}`;
  remove.setAttribute('aria-label', `Remove ${name}${k}`);
  remove.addEventListener('click', () => handlers.onRemove(k));
  td.append(remove);
  tr.append(td);
  return tr;
}
