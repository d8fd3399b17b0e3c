// Frame names as HTML labels over the canvas, only while labels are on, and only for the
// frames nearest the camera so that a large tree stays cheap and readable.
import * as THREE from '/three/build/three.module.js';

const MAX_LABELS = 80;

export class FrameLabels {
  constructor(layer) {
    this.layer = layer;
    this.enabled = false;
    this.pool = [];
    this.shown = 0;
    this.point = new THREE.Vector3();
  }

  setEnabled(enabled) {
    this.enabled = enabled;
    if (!enabled) this.hideFrom(0);
  }

  // Places the labels for the frames of `store` as seen by `view`'s camera.
  update(store, view, selected) {
    if (!this.enabled) return;
    const camera = view.camera;
    const width = view.width;
    const height = view.height;
    const candidates = [];
    for (const [name, pose] of store.poses) {
      this.point.set(pose[0], pose[1], pose[2]);
      const distance = this.point.distanceTo(camera.position);
      this.point.project(camera);
      if (this.point.z > 1 || Math.abs(this.point.x) > 1.05 || Math.abs(this.point.y) > 1.05) continue;
      candidates.push({
        name,
        distance: name === selected ? -1 : distance,
        x: (this.point.x + 1) * 0.5 * width,
        y: (1 - this.point.y) * 0.5 * height,
      });
    }
    if (candidates.length > MAX_LABELS) {
      candidates.sort((a, b) => a.distance - b.distance);
      candidates.length = MAX_LABELS;
    }
    candidates.forEach((candidate, i) => {
      const label = this.labelAt(i);
      if (label.textContent !== candidate.name) label.textContent = candidate.name;
      label.style.transform = `translate(${candidate.x + 4}px, ${candidate.y - 8}px)`;
      label.className = 'frame-label' + (store.stale.has(candidate.name) ? ' stale' : '') +
        (candidate.name === selected ? ' selected' : '');
      label.style.display = '';
    });
    this.hideFrom(candidates.length);
  }

  labelAt(i) {
    while (this.pool.length <= i) {
      const label = document.createElement('div');
      label.className = 'frame-label';
      this.layer.appendChild(label);
      this.pool.push(label);
    }
    return this.pool[i];
  }

  hideFrom(first) {
    for (let i = first; i < this.pool.length; i += 1) this.pool[i].style.display = 'none';
    this.shown = Math.min(first, this.pool.length);
  }
}
