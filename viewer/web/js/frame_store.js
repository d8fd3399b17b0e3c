// What the server has told this page about the frames: the poses of the last scene (each
// frame's pose in the fixed frame, [x, y, z, qx, qy, qz, qw]) and the tree from `tree` messages.

function isPose(value) {
  return Array.isArray(value) && value.length === 7 && value.every(Number.isFinite);
}

function stringList(value) {
  return Array.isArray(value) ? value.filter((item) => typeof item === 'string') : [];
}

export class FrameStore {
  constructor() {
    this.reset();
  }

  // Forgets everything (a new connection starts from a full scene).
  reset() {
    this.poses = new Map();
    this.stale = new Set();
    this.unconnected = [];
    this.fixedFrame = null;
    this.time = 0;
    this.live = true;
    this.history = { oldest: 0, newest: 0 };
    this.sceneCount = 0;
    this.lastSceneFull = false;
    // name -> {parent, authority, static, rate_hz, age_s, stale}, for frames with a parent.
    this.frames = new Map();
    this.roots = [];
    this.structureKey = '';
    // Counts on across resets, so that whoever drew the old tree sees that it changed.
    this.structureVersion = (this.structureVersion || 0) + 1;
  }

  applyScene(msg) {
    if (msg.full === true) this.poses.clear();
    if (msg.poses && typeof msg.poses === 'object') {
      for (const [name, pose] of Object.entries(msg.poses)) {
        if (isPose(pose)) this.poses.set(name, pose);
      }
    }
    for (const name of stringList(msg.removed)) this.poses.delete(name);
    this.stale = new Set(stringList(msg.stale));
    this.unconnected = Array.isArray(msg.unconnected)
      ? msg.unconnected.filter((tree) => tree && typeof tree.root === 'string')
          .map((tree) => ({ root: tree.root, frames: stringList(tree.frames) }))
      : [];
    if (typeof msg.fixed_frame === 'string') this.fixedFrame = msg.fixed_frame;
    if (Number.isFinite(msg.time)) this.time = msg.time;
    this.live = msg.live !== false;
    if (msg.history && Number.isFinite(msg.history.oldest) && Number.isFinite(msg.history.newest)) {
      this.history = { oldest: msg.history.oldest, newest: msg.history.newest };
    }
    this.lastSceneFull = msg.full === true;
    this.sceneCount += 1;
  }

  applyTree(msg) {
    const frames = new Map();
    if (Array.isArray(msg.frames)) {
      for (const frame of msg.frames) {
        if (!frame || typeof frame.name !== 'string' || typeof frame.parent !== 'string') continue;
        frames.set(frame.name, frame);
      }
    }
    this.frames = frames;
    this.roots = stringList(msg.roots);
    const key = [...frames.values()].map((f) => `${f.name}<${f.parent}`).sort().join('\n') +
      '\n|' + [...this.roots].sort().join('\n');
    if (key !== this.structureKey) {
      this.structureKey = key;
      this.structureVersion += 1;
    }
  }

  parentOf(name) {
    const frame = this.frames.get(name);
    return frame ? frame.parent : null;
  }

  // Every frame known from the tree or the scene, sorted.
  allFrameNames() {
    const names = new Set(this.roots);
    for (const [name, frame] of this.frames) {
      names.add(name);
      names.add(frame.parent);
    }
    for (const name of this.poses.keys()) names.add(name);
    return [...names].sort();
  }
}
