// Loads the robot's mesh files (STL and COLLADA) from the viewer's /mesh/ URLs, once per URL.
import { STLLoader } from '/three/examples/jsm/loaders/STLLoader.js';
import { ColladaLoader } from '/three/examples/jsm/loaders/ColladaLoader.js';

export class MeshLoader {
  constructor() {
    this.cache = new Map();
  }

  // Forgets every mesh (a new robot may give the same URL to another file).
  clear() {
    for (const promise of this.cache.values()) {
      promise.then(disposeTemplate, () => {});
    }
    this.cache.clear();
  }

  // Resolves to {format: 'stl', geometry} or {format: 'dae', scene}; rejects with an Error that
  // says why the file could not be used.
  load(url, format) {
    const key = `${format} ${url}`;
    if (!this.cache.has(key)) this.cache.set(key, fetchMesh(url, format));
    return this.cache.get(key);
  }
}

async function fetchMesh(url, format) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`HTTP ${response.status} ${response.statusText}`.trim());
  if (format === 'stl') {
    let geometry;
    try {
      geometry = new STLLoader().parse(await response.arrayBuffer());
    } catch (error) {
      throw new Error(`not an STL file three.js can read (${error.message})`);
    }
    const position = geometry.getAttribute('position');
    if (!position || position.count === 0) throw new Error('the STL file holds no triangles');
    return { format, geometry };
  }
  if (format === 'dae') {
    const text = await response.text();
    if (!text.includes('<COLLADA')) throw new Error('not a COLLADA file');
    const baseUrl = url.slice(0, url.lastIndexOf('/') + 1);
    const collada = new ColladaLoader().parse(text, baseUrl);
    if (!collada || !collada.scene) throw new Error('not a COLLADA file three.js can read');
    // ColladaLoader turns a Z_UP file to three's y up. A URDF means a mesh in its own axes
    // (as RViz draws it), so the turn is undone; the file's unit scale stays.
    collada.scene.quaternion.set(0, 0, 0, 1);
    return { format, scene: collada.scene };
  }
  throw new Error(`meshes of format '${format}' are not drawn`);
}

function disposeTemplate(template) {
  if (template.geometry) template.geometry.dispose();
  if (template.scene) {
    template.scene.traverse((object) => {
      if (object.geometry) object.geometry.dispose();
    });
  }
}
