// Undo and redo: snapshots of the edited state ({curves, second, active}) taken before
// each edit. A new edit clears the redo list. A run of small moves of one point by the
// keyboard is one step (the caller passes the same `merge` key for them).

const kDepth = 200;

export class EditHistory {
  constructor() {
    this.past = [];  // [{snapshot, source, merge}]
    this.future = [];
  }

  /** Records `snapshot` (the state before an edit made through `source`). */
  record(snapshot, source, merge = null) {
    const last = this.past[this.past.length - 1];
    if (merge !== null && last && last.merge === merge) return;
    this.past.push({snapshot, source, merge});
    if (this.past.length > kDepth) this.past.shift();
    this.future = [];
  }

  get canUndo() { return this.past.length > 0; }
  get canRedo() { return this.future.length > 0; }

  /** The snapshot to go back to from `current`, or null. */
  undo(current) {
    const entry = this.past.pop();
    if (!entry) return null;
    this.future.push({...entry, snapshot: current, merge: null});
    return entry.snapshot;
  }

  /** The snapshot to go forward to from `current`, or null. */
  redo(current) {
    const entry = this.future.pop();
    if (!entry) return null;
    this.past.push({...entry, snapshot: current, merge: null});
    return entry.snapshot;
  }

  /** Takes back the last edit for good (it was refused): its snapshot and source, or null. */
  drop() {
    const entry = this.past.pop();
    return entry ? {snapshot: entry.snapshot, source: entry.source} : null;
  }
}
