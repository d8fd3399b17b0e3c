// The selected frame's pose in the fixed frame: position, roll-pitch-yaw and quaternion.
import { formatAge, formatRate } from './tree_panel.js';

// Roll, pitch, yaw in radians of a unit quaternion, for rotation = Rz(yaw) Ry(pitch) Rx(roll).
export function quaternionToRpy(x, y, z, w) {
  const roll = Math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
  const pitch = Math.asin(Math.max(-1, Math.min(1, 2 * (w * y - z * x))));
  const yaw = Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  return [roll, pitch, yaw];
}

const DEGREES = 180 / Math.PI;

export class PosePanel {
  constructor(box) {
    this.box = box;
    this.name = null;
    this.cells = null;
  }

  // Shows `name` (null: nothing selected).
  select(name) {
    this.name = name;
    this.cells = null;
    this.box.replaceChildren();
    this.box.classList.toggle('muted', name === null);
    if (name === null) {
      this.box.textContent = 'Click a frame in the tree.';
      return;
    }
    const title = document.createElement('div');
    title.className = 'selected-name';
    title.textContent = name;
    const table = document.createElement('table');
    table.className = 'pose-table';
    const cells = {};
    const row = (label, keys) => {
      const tr = document.createElement('tr');
      const th = document.createElement('th');
      th.textContent = label;
      tr.appendChild(th);
      for (const key of keys) {
        const td = document.createElement('td');
        td.id = `pose-${key}`;
        cells[key] = td;
        tr.appendChild(td);
      }
      table.appendChild(tr);
    };
    row('xyz (m)', ['x', 'y', 'z']);
    row('rpy (°)', ['roll', 'pitch', 'yaw']);
    row('quat xyzw', ['qx', 'qy', 'qz', 'qw']);
    const meta = document.createElement('div');
    meta.className = 'pose-meta';
    this.box.append(title, table, meta);
    this.cells = cells;
    this.meta = meta;
  }

  update(store) {
    if (this.name === null || this.cells === null) return;
    const pose = store.poses.get(this.name);
    const cells = this.cells;
    const set = (key, text) => {
      if (cells[key].textContent !== text) cells[key].textContent = text;
    };
    if (pose) {
      const [x, y, z, qx, qy, qz, qw] = pose;
      const rpy = quaternionToRpy(qx, qy, qz, qw);
      set('x', x.toFixed(3));
      set('y', y.toFixed(3));
      set('z', z.toFixed(3));
      set('roll', (rpy[0] * DEGREES).toFixed(2));
      set('pitch', (rpy[1] * DEGREES).toFixed(2));
      set('yaw', (rpy[2] * DEGREES).toFixed(2));
      set('qx', qx.toFixed(4));
      set('qy', qy.toFixed(4));
      set('qz', qz.toFixed(4));
      set('qw', qw.toFixed(4));
    } else {
      for (const key of Object.keys(cells)) set(key, '–');
    }
    const frame = store.frames.get(this.name);
    const where = `in ${store.fixedFrame || '?'}` + (pose ? '' : ' (not drawn)');
    let text = where;
    if (frame) {
      const timing = frame.static ? 'static' : `${formatRate(frame.rate_hz)}, ${formatAge(frame.age_s)} old`;
      text += ` · parent ${frame.parent} · ${timing}${frame.stale ? ' · stale' : ''}` +
        ` · from ${frame.authority}`;
    } else {
      text += ' · a root frame';
    }
    if (this.meta.textContent !== text) this.meta.textContent = text;
  }
}
