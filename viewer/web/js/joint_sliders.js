// One slider per movable joint of the robot, and the switch that makes the viewer publish
// their positions as joint states.

// A slider the user touched this recently keeps its value over the server's echo.
const USER_HOLD_MS = 1000;

function formatPosition(joint, value) {
  return joint.type === 'prismatic' ? `${value.toFixed(3)} m` : `${(value * 180 / Math.PI).toFixed(1)}°`;
}

export class JointSliders {
  // onSend(enabled, positions) is called when the switch flips and, while it is on, when a
  // slider moves (the caller throttles).
  constructor({ box, toggle, onSend }) {
    this.box = box;
    this.toggle = toggle;
    this.onSend = onSend;
    this.sliders = new Map();
    toggle.addEventListener('change', () => {
      this.box.classList.toggle('disabled', !toggle.checked);
      this.onSend(toggle.checked, this.positions());
    });
    this.box.classList.add('disabled');
  }

  get enabled() {
    return this.toggle.checked;
  }

  // Builds the sliders of `robot`'s joints that have `slider: true` (none for null).
  setRobot(robot) {
    this.sliders.clear();
    this.box.replaceChildren();
    const joints = robot && Array.isArray(robot.joints)
      ? robot.joints.filter((joint) => joint && joint.slider === true && typeof joint.name === 'string' &&
          Number.isFinite(joint.lower) && Number.isFinite(joint.upper) && joint.lower <= joint.upper)
      : [];
    this.box.classList.toggle('muted', joints.length === 0);
    if (joints.length === 0) {
      this.box.textContent = robot ? 'The robot has no movable joints.' : 'No robot description.';
      return;
    }
    for (const joint of joints) {
      const row = document.createElement('div');
      row.className = 'joint-row';
      const name = document.createElement('label');
      name.className = 'joint-name';
      name.textContent = joint.name;
      const slider = document.createElement('input');
      slider.type = 'range';
      slider.min = String(joint.lower);
      slider.max = String(joint.upper);
      slider.step = 'any';
      slider.dataset.joint = joint.name;
      // At rest as the joint publisher has it: zero, or the middle of the limits.
      const rest = joint.lower <= 0 && joint.upper >= 0 ? 0 : (joint.lower + joint.upper) / 2;
      slider.value = String(rest);
      const output = document.createElement('output');
      const entry = { joint, slider, output, touchedAt: -Infinity };
      output.textContent = formatPosition(joint, rest);
      slider.addEventListener('input', () => {
        entry.touchedAt = performance.now();
        output.textContent = formatPosition(joint, Number(slider.value));
        if (this.enabled) this.onSend(true, this.positions());
      });
      name.htmlFor = slider.id = `joint-${this.sliders.size}`;
      row.append(name, slider, output);
      this.box.appendChild(row);
      this.sliders.set(joint.name, entry);
    }
  }

  positions() {
    const positions = {};
    for (const [name, entry] of this.sliders) positions[name] = Number(entry.slider.value);
    return positions;
  }

  // Takes the server's view of this page's sliders (a `joints` message).
  applyServerState(msg) {
    if (typeof msg.publishing === 'boolean' && msg.publishing !== this.toggle.checked) {
      this.toggle.checked = msg.publishing;
      this.box.classList.toggle('disabled', !msg.publishing);
    }
    if (!msg.positions || typeof msg.positions !== 'object') return;
    const now = performance.now();
    for (const [name, value] of Object.entries(msg.positions)) {
      const entry = this.sliders.get(name);
      if (!entry || !Number.isFinite(value) || now - entry.touchedAt < USER_HOLD_MS) continue;
      entry.slider.value = String(value);
      entry.output.textContent = formatPosition(entry.joint, value);
    }
  }
}
