// Every drawn frame as three short lines (x red, y green, z blue) and a line from its parent,
// all in two LineSegments objects so that a thousand frames cost two draw calls.
import * as THREE from '/three/build/three.module.js';

const AXIS_RGB = [[0.95, 0.26, 0.26], [0.32, 0.86, 0.36], [0.3, 0.52, 1.0]];
const STALE_RGB = [0.42, 0.45, 0.5];
const LINK_RGB = [0.86, 0.78, 0.42];
const STALE_LINK_RGB = [0.36, 0.38, 0.42];

// A LineSegments whose vertex buffers grow as needed; the draw range says how much is used.
class LineBuffer {
  constructor(opacity) {
    this.material = new THREE.LineBasicMaterial({
      vertexColors: THREE.VertexColors, transparent: opacity < 1, opacity,
    });
    this.lines = new THREE.LineSegments(new THREE.BufferGeometry(), this.material);
    this.lines.frustumCulled = false;
    this.capacity = 0;
    this.allocate(64);
  }

  allocate(vertices) {
    const geometry = new THREE.BufferGeometry();
    this.positions = new Float32Array(vertices * 3);
    this.colors = new Float32Array(vertices * 3);
    geometry.setAttribute('position', new THREE.BufferAttribute(this.positions, 3)
      .setUsage(THREE.DynamicDrawUsage));
    geometry.setAttribute('color', new THREE.BufferAttribute(this.colors, 3)
      .setUsage(THREE.DynamicDrawUsage));
    this.lines.geometry.dispose();
    this.lines.geometry = geometry;
    this.capacity = vertices;
  }

  // Makes room for `vertices` vertices, dropping what was written.
  reserve(vertices) {
    if (vertices > this.capacity) this.allocate(Math.max(vertices, this.capacity * 2));
    this.count = 0;
  }

  push(x, y, z, rgb) {
    const i = this.count * 3;
    this.positions[i] = x;
    this.positions[i + 1] = y;
    this.positions[i + 2] = z;
    this.colors[i] = rgb[0];
    this.colors[i + 1] = rgb[1];
    this.colors[i + 2] = rgb[2];
    this.count += 1;
  }

  commit() {
    const geometry = this.lines.geometry;
    geometry.setDrawRange(0, this.count);
    geometry.attributes.position.needsUpdate = true;
    geometry.attributes.color.needsUpdate = true;
  }
}

export class FrameAxes {
  constructor() {
    this.axes = new LineBuffer(1.0);
    this.links = new LineBuffer(0.55);
    this.group = new THREE.Group();
    this.group.add(this.axes.lines, this.links.lines);
    this.size = 0.1;
  }

  // Redraws every frame of the store at its pose; `selected` is drawn twice as large.
  update(store, selected) {
    const poses = store.poses;
    this.axes.reserve(poses.size * 6);
    this.links.reserve(poses.size * 2);
    for (const [name, pose] of poses) {
      const [px, py, pz, x, y, z, w] = pose;
      const stale = store.stale.has(name);
      const length = name === selected ? this.size * 2 : this.size;
      // The columns of the rotation matrix are the frame's axes in the fixed frame.
      const columns = [
        [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
        [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
        [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
      ];
      for (let axis = 0; axis < 3; axis += 1) {
        const rgb = stale ? STALE_RGB : AXIS_RGB[axis];
        const c = columns[axis];
        this.axes.push(px, py, pz, rgb);
        this.axes.push(px + c[0] * length, py + c[1] * length, pz + c[2] * length, rgb);
      }
      const parent = poses.get(store.parentOf(name));
      if (parent) {
        const rgb = stale ? STALE_LINK_RGB : LINK_RGB;
        this.links.push(parent[0], parent[1], parent[2], rgb);
        this.links.push(px, py, pz, rgb);
      }
    }
    this.axes.commit();
    this.links.commit();
  }
}
