// The robot's visuals from a `robot` message: one group per link, placed at the pose of the
// frame of the same name; boxes, cylinders, spheres and meshes at their visual origins.
import * as THREE from '/three/build/three.module.js';
import { MeshLoader } from './mesh_loader.js';

const NEUTRAL_GREY = [0.72, 0.73, 0.75, 1];

function finiteList(value, length) {
  return Array.isArray(value) && value.length === length && value.every(Number.isFinite);
}

function positive(value) {
  return Number.isFinite(value) && value > 0;
}

function makeMaterial(rgba, doubleSided) {
  const [r, g, b, a] = finiteList(rgba, 4) ? rgba : NEUTRAL_GREY;
  return new THREE.MeshPhongMaterial({
    color: new THREE.Color(r, g, b), opacity: a, transparent: a < 1, shininess: 40,
    side: doubleSided ? THREE.DoubleSide : THREE.FrontSide,
  });
}

// The three.js geometry of a box, cylinder or sphere, in URDF's axes; null for other kinds.
function primitiveGeometry(geometry) {
  switch (geometry.kind) {
    case 'box':
      if (!finiteList(geometry.size, 3) || !geometry.size.every((s) => s >= 0)) return null;
      return new THREE.BoxBufferGeometry(...geometry.size);
    case 'cylinder': {
      if (!positive(geometry.radius) || !positive(geometry.length)) return null;
      // three's cylinders run along y, URDF's along z.
      const cylinder = new THREE.CylinderBufferGeometry(
        geometry.radius, geometry.radius, geometry.length, 32);
      cylinder.rotateX(Math.PI / 2);
      return cylinder;
    }
    case 'sphere':
      if (!positive(geometry.radius)) return null;
      return new THREE.SphereBufferGeometry(geometry.radius, 32, 16);
    default:
      return null;
  }
}

export class RobotModel {
  // onChange() is called when a mesh arrives or fails, after the robot was set.
  constructor({ onChange }) {
    this.group = new THREE.Group();
    this.meshLoader = new MeshLoader();
    this.onChange = onChange;
    this.links = new Map();
    this.robot = null;
    this.generation = 0;
    this.resetCounts();
  }

  resetCounts() {
    this.meshesLoaded = 0;
    this.meshesFailed = 0;
    this.meshesPending = 0;
    this.visualCount = 0;
    this.warnings = [];
  }

  // Replaces the drawn robot (null: none).
  setRobot(robot) {
    this.clear();
    this.robot = robot && Array.isArray(robot.links) ? robot : null;
    if (!this.robot) return;
    for (const link of this.robot.links) {
      if (!link || typeof link.name !== 'string') continue;
      const linkGroup = new THREE.Group();
      linkGroup.name = link.name;
      linkGroup.visible = false;
      for (const visual of Array.isArray(link.visuals) ? link.visuals : []) {
        this.addVisual(linkGroup, link.name, visual);
      }
      this.links.set(link.name, linkGroup);
      this.group.add(linkGroup);
    }
  }

  clear() {
    this.generation += 1;
    for (const linkGroup of this.links.values()) {
      this.group.remove(linkGroup);
      linkGroup.traverse((object) => {
        if (object.userData.ownsGeometry) object.geometry.dispose();
        if (object.userData.ownsMaterial) object.material.dispose();
      });
    }
    this.links.clear();
    this.meshLoader.clear();
    this.resetCounts();
  }

  addVisual(linkGroup, linkName, visual) {
    if (!visual || !visual.geometry) return;
    const holder = new THREE.Group();
    if (finiteList(visual.origin, 7)) {
      const [x, y, z, qx, qy, qz, qw] = visual.origin;
      holder.position.set(x, y, z);
      holder.quaternion.set(qx, qy, qz, qw).normalize();
    }
    linkGroup.add(holder);
    this.visualCount += 1;
    const geometry = visual.geometry;
    if (geometry.kind === 'mesh') {
      this.addMesh(holder, linkName, geometry, visual.color);
      return;
    }
    const shape = primitiveGeometry(geometry);
    if (!shape) {
      this.warnings.push(`link '${linkName}': a ${geometry.kind} visual with unusable sizes is not drawn`);
      return;
    }
    const mesh = new THREE.Mesh(shape, makeMaterial(visual.color, false));
    mesh.userData.ownsGeometry = true;
    mesh.userData.ownsMaterial = true;
    holder.add(mesh);
  }

  addMesh(holder, linkName, geometry, color) {
    const url = geometry.url;
    if (typeof url !== 'string') {
      this.meshFailed(linkName, String(url), 'no URL');
      return;
    }
    if (finiteList(geometry.scale, 3)) holder.scale.set(...geometry.scale);
    const generation = this.generation;
    this.meshesPending += 1;
    this.meshLoader.load(url, geometry.format).then((template) => {
      if (generation !== this.generation) return;
      this.meshesPending -= 1;
      holder.add(this.instantiate(template, color));
      this.meshesLoaded += 1;
      this.onChange();
    }).catch((error) => {
      if (generation !== this.generation) return;
      this.meshesPending -= 1;
      this.meshFailed(linkName, url, error && error.message ? error.message : String(error));
      this.onChange();
    });
  }

  meshFailed(linkName, url, why) {
    this.meshesFailed += 1;
    this.warnings.push(`link '${linkName}': mesh ${url} was not drawn: ${why}`);
  }

  // A drawable copy of a loaded mesh; an STL takes the visual's colour (or grey), a COLLADA
  // mesh keeps its own materials unless the URDF gives a colour.
  instantiate(template, color) {
    if (template.format === 'stl') {
      const mesh = new THREE.Mesh(template.geometry, makeMaterial(color, true));
      mesh.userData.ownsMaterial = true;
      return mesh;
    }
    const copy = template.scene.clone(true);
    if (finiteList(color, 4)) {
      const material = makeMaterial(color, true);
      copy.traverse((object) => {
        if (!object.isMesh) return;
        object.material = material;
        object.userData.ownsMaterial = true;
      });
    }
    return copy;
  }

  // Puts each link at its frame's pose in the store; links whose frame is not drawn are hidden.
  update(store) {
    for (const [name, linkGroup] of this.links) {
      const pose = store.poses.get(name);
      linkGroup.visible = pose !== undefined;
      if (!pose) continue;
      linkGroup.position.set(pose[0], pose[1], pose[2]);
      linkGroup.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
    }
  }

  // The box around every visible visual (empty when nothing is drawn).
  boundingBox() {
    const box = new THREE.Box3();
    this.group.updateMatrixWorld(true);
    for (const linkGroup of this.links.values()) {
      if (linkGroup.visible) box.expandByObject(linkGroup);
    }
    return box;
  }
}
