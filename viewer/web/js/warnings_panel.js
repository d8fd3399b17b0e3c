// The warnings list: the robot description's own warnings, meshes that could not be drawn,
// and the last few messages the server refused.

const KEPT_ERRORS = 5;

export class WarningsPanel {
  constructor({ list, count }) {
    this.list = list;
    this.count = count;
    this.errors = [];
    this.key = '';
  }

  addError(message) {
    this.errors.push(String(message));
    if (this.errors.length > KEPT_ERRORS) this.errors.shift();
  }

  // Shows `warnings` (strings) and the kept errors; rebuilds the list only when they changed.
  show(warnings) {
    const key = warnings.join('\n') + '\n|' + this.errors.join('\n');
    if (key === this.key) return;
    this.key = key;
    const items = [];
    for (const text of warnings) {
      const li = document.createElement('li');
      li.textContent = text;
      items.push(li);
    }
    for (const text of this.errors) {
      const li = document.createElement('li');
      li.className = 'error';
      li.textContent = `server: ${text}`;
      items.push(li);
    }
    this.list.replaceChildren(...items);
    const total = warnings.length + this.errors.length;
    this.count.textContent = total > 0 ? `(${total})` : '';
  }
}
