// The three.js scene: renderer, z-up camera with orbit controls, lights and ground grid.
// Everything is drawn in the fixed frame's coordinates (metres, z up).
import * as THREE from '/three/build/three.module.js';
import { OrbitControls } from '/three/examples/jsm/controls/OrbitControls.js';

// WebGL drawn by the CPU (SwiftShader, llvmpipe): no GPU to smooth edges for free.
function softwareWebGl() {
  const gl = document.createElement('canvas').getContext('webgl');
  if (!gl) return true;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|software/i.test(renderer);
}

// Edges are smoothed unless WebGL runs on the CPU, where it costs the most; ?antialias=1 or
// ?antialias=0 in the page's URL decides instead.
function wantAntialias() {
  const asked = new URLSearchParams(location.search).get('antialias');
  if (asked === '1' || asked === '0') return asked === '1';
  return !softwareWebGl();
}

export class SceneView {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: wantAntialias() });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0x1b1e24);
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.01, 500);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(2.5, -2.5, 1.8);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.set(0, 0, 0.4);
    this.controls.update();
    this.userMovedCamera = false;
    this.controls.addEventListener('start', () => { this.userMovedCamera = true; });
    this.controls.addEventListener('change', () => { this.needsRender = true; });

    this.scene.add(new THREE.HemisphereLight(0xe8eef8, 0x30343c, 0.75));
    const sun = new THREE.DirectionalLight(0xffffff, 0.7);
    sun.position.set(3, -2, 5);
    this.scene.add(sun);
    const fill = new THREE.DirectionalLight(0xffffff, 0.25);
    fill.position.set(-3, 4, 2);
    this.scene.add(fill);

    this.scene.add(makeGround());

    this.needsRender = true;
    this.resize();
    window.addEventListener('resize', () => this.resize());
  }

  add(object) {
    this.scene.add(object);
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.needsRender = true;
  }

  get width() {
    return this.renderer.domElement.clientWidth;
  }

  get height() {
    return this.renderer.domElement.clientHeight;
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.needsRender = false;
  }

  // Points the camera at a box (THREE.Box3) so that all of it is in view, from the front
  // right and above, as a robot is usually looked at.
  frameBox(box) {
    if (box.isEmpty()) return;
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.3, box.getSize(new THREE.Vector3()).length() / 2);
    const halfFov = (this.camera.fov / 2) * (Math.PI / 180);
    const fitFov = this.camera.aspect < 1 ? Math.atan(Math.tan(halfFov) * this.camera.aspect) : halfFov;
    const distance = radius / Math.sin(fitFov);
    const direction = new THREE.Vector3(1.0, -0.9, 0.65).normalize();
    this.camera.position.copy(center).addScaledVector(direction, distance);
    this.camera.near = Math.max(0.001, distance / 200);
    this.camera.far = Math.max(100, distance * 20);
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    this.needsRender = true;
  }
}

// A 20 m grid in the xy plane with 1 m cells, brighter through the origin. Its lines are cut
// into 1 m pieces: a long line that passes behind the camera is dropped whole by some
// renderers (SwiftShader) instead of being clipped.
function makeGround() {
  const half = 10;
  const positions = [];
  const colors = [];
  const minor = new THREE.Color(0x3f4654);
  const major = new THREE.Color(0x6b7587);
  for (let line = -half; line <= half; line += 1) {
    const color = line === 0 ? major : minor;
    for (let piece = -half; piece < half; piece += 1) {
      positions.push(piece, line, 0, piece + 1, line, 0);
      positions.push(line, piece, 0, line, piece + 1, 0);
      for (let i = 0; i < 4; i += 1) colors.push(color.r, color.g, color.b);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.Float32BufferAttribute(colors, 3));
  return new THREE.LineSegments(geometry,
    new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors }));
}
