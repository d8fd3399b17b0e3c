// The page: wires the connection to the scene, the panels and the controls.
import * as THREE from '/three/build/three.module.js';
import { Connection } from './connection.js';
import { throttle } from './throttle.js';
import { FrameStore } from './frame_store.js';
import { SceneView } from './scene_view.js';
import { FrameAxes } from './frame_axes.js';
import { FrameLabels } from './frame_labels.js';
import { RobotModel } from './robot_model.js';
import { TreePanel } from './tree_panel.js';
import { PosePanel } from './pose_panel.js';
import { Timeline } from './timeline.js';
import { JointSliders } from './joint_sliders.js';
import { WarningsPanel } from './warnings_panel.js';
import { FpsMeter, createPageStats } from './page_stats.js';

// Scrubbing and joint sliders send at most this often (20 a second).
const SEND_INTERVAL_MS = 50;

const $ = (id) => document.getElementById(id);

const stats = createPageStats();
window.lcmtfViewer = stats;

const store = new FrameStore();
const view = new SceneView($('view'));
const axes = new FrameAxes();
view.add(axes.group);
const labels = new FrameLabels($('labels'));
const robot = new RobotModel({ onChange: onRobotChange });
view.add(robot.group);
const posePanel = new PosePanel($('selected-pose'));
const warningsPanel = new WarningsPanel({ list: $('warnings'), count: $('warning-count') });
const treePanel = new TreePanel({
  list: $('frame-tree'), search: $('frame-search'), count: $('frame-count'),
  unconnectedBox: $('unconnected'), onSelect: select,
});
const timeline = new Timeline({
  button: $('play-pause'), slider: $('time-slider'), label: $('time-label'),
  onPlay: () => { pausedTime = null; sendView(); },
  onPause: (time) => { pausedTime = time; sendView(); },
  onScrub: (time) => { pausedTime = time; sendViewThrottled(); },
});
const sendJoints = throttle((enabled, positions) => {
  connection.send({ type: 'joints', enabled, positions });
}, SEND_INTERVAL_MS);
const jointSliders = new JointSliders({
  box: $('joint-sliders'), toggle: $('joints-switch'),
  onSend: (enabled, positions) => {
    sendJoints(enabled, positions);
    // The switch takes effect at once, not at the end of the interval.
    if (!enabled) sendJoints.flush();
  },
});

let selected = null;
let pendingAck = null; // the seq of a scene received and not yet drawn
let sceneChanged = false;
let pausedTime = null; // null: live
let chosenFixedFrame = null; // the user's choice, sent again after reconnecting
let viewSentAt = null;
let fitPending = true;
let fittedFrames = 0; // frames drawn when the camera was last fitted by itself
let frameOptionsKey = '';
let shownFixedFrame = null; // the server's fixed frame when the choices were last updated
const hudFps = $('hud-fps');
const renderMeter = new FpsMeter();
const frameMeter = new FpsMeter();

const connection = new Connection(socketUrl(), { onMessage: handleMessage, onState: showConnection });

function socketUrl() {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/ws`;
}

// --- Messages from the server ---------------------------------------------------------------

function handleMessage(msg) {
  switch (msg.type) {
    case 'hello': return onHello(msg);
    case 'robot': return onRobot(msg.robot);
    case 'scene': return onScene(msg);
    case 'tree': return onTree(msg);
    case 'joints':
      jointSliders.applyServerState(msg);
      stats.jointsPublishing = msg.publishing === true;
      return undefined;
    case 'error':
      warningsPanel.addError(msg.message);
      stats.errors = warningsPanel.errors.slice();
      showWarnings();
      return undefined;
    default:
      console.warn('lcmtf viewer: unknown message', msg.type);
      return undefined;
  }
}

function onHello(msg) {
  stats.serverVersion = typeof msg.version === 'string' ? msg.version : null;
  store.reset();
  fittedFrames = 0;
  pendingAck = null;
  sceneChanged = true;
  // A new connection starts live, in the user's fixed frame if one was chosen.
  pausedTime = null;
  timeline.setPaused(false);
  if (chosenFixedFrame !== null) sendView();
}

function onRobot(description) {
  robot.setRobot(description);
  jointSliders.setRobot(robot.robot);
  stats.robotLoaded = robot.robot !== null;
  stats.robotName = robot.robot && typeof robot.robot.name === 'string' ? robot.robot.name : null;
  fitPending = !view.userMovedCamera;
  onRobotChange();
}

function onRobotChange() {
  stats.meshesLoaded = robot.meshesLoaded;
  stats.meshesFailed = robot.meshesFailed;
  stats.meshesPending = robot.meshesPending;
  if (robot.meshesPending === 0 && !view.userMovedCamera) fitPending = true;
  robot.update(store);
  showWarnings();
  view.needsRender = true;
}

function onScene(msg) {
  store.applyScene(msg);
  if (Number.isInteger(msg.seq)) pendingAck = msg.seq;
  sceneChanged = true;
}

function onTree(msg) {
  store.applyTree(msg);
  treePanel.update(store);
  updateFixedFrameChoices();
  posePanel.update(store);
  stats.framesListed = treePanel.listedCount;
}

function showWarnings() {
  const robotWarnings = robot.robot && Array.isArray(robot.robot.warnings)
    ? robot.robot.warnings.map(String) : [];
  const all = robotWarnings.concat(robot.warnings);
  warningsPanel.show(all);
  stats.warnings = all;
}

function showConnection(state, detail) {
  stats.connection = state;
  const badge = $('connection-state');
  badge.className = `state-${state}`;
  if (state === 'open') {
    badge.textContent = 'connected';
    badge.title = connection.url;
  } else if (state === 'connecting') {
    badge.textContent = 'connecting…';
  } else {
    badge.textContent = `disconnected, retrying in ${(detail.inMs / 1000).toFixed(1)} s`;
    badge.title = `closed: ${detail.reason}`;
  }
}

// --- What the page asks for ------------------------------------------------------------------

// Asks for the chosen fixed frame, live or at the paused time.
function postView() {
  const fixedFrame = chosenFixedFrame !== null ? chosenFixedFrame : store.fixedFrame;
  if (fixedFrame === null) return;
  if (connection.send({ type: 'view', fixed_frame: fixedFrame, time: pausedTime })) {
    viewSentAt = performance.now();
  }
}
const sendViewThrottled = throttle(postView, SEND_INTERVAL_MS);
function sendView() {
  sendViewThrottled.cancel();
  postView();
}

function select(name) {
  selected = name;
  stats.selected = name;
  treePanel.setSelected(name);
  posePanel.select(name);
  posePanel.update(store);
  sceneChanged = true;
}

function updateFixedFrameChoices() {
  const names = store.allFrameNames();
  const current = chosenFixedFrame !== null ? chosenFixedFrame : store.fixedFrame;
  if (current !== null && !names.includes(current)) names.push(current);
  const key = names.join('\n');
  const selectBox = $('fixed-frame');
  shownFixedFrame = store.fixedFrame;
  if (key !== frameOptionsKey) {
    frameOptionsKey = key;
    selectBox.replaceChildren(...names.map((name) => new Option(name, name)));
  }
  if (current !== null && selectBox.value !== current && document.activeElement !== selectBox) {
    selectBox.value = current;
  }
}

// Frames the robot (its visuals and link frames) when one is drawn, else every frame.
function fitView() {
  const box = robot.boundingBox();
  const point = new THREE.Vector3();
  const robotOnly = !box.isEmpty();
  for (const [name, pose] of store.poses) {
    if (robotOnly && !robot.links.has(name)) continue;
    box.expandByPoint(point.set(pose[0], pose[1], pose[2]));
  }
  view.frameBox(box);
}

$('fixed-frame').addEventListener('change', (event) => {
  chosenFixedFrame = event.target.value;
  sendView();
});
$('show-labels').addEventListener('change', (event) => {
  labels.setEnabled(event.target.checked);
  view.needsRender = true;
});
$('axis-size').addEventListener('change', (event) => {
  axes.size = Number(event.target.value) || 0.1;
  sceneChanged = true;
});
$('fit-view').addEventListener('click', () => {
  fitView();
  view.userMovedCamera = false;
});

// Helpers for tests and scripts.
stats.pose = (name) => {
  const pose = store.poses.get(name);
  return pose ? pose.slice() : null;
};
stats.poses = () => Object.fromEntries(store.poses);
stats.select = select;
stats.fitView = fitView;
stats.camera = () => ({ position: view.camera.position.toArray(), target: view.controls.target.toArray() });
stats.setLabels = (enabled) => {
  $('show-labels').checked = enabled;
  labels.setEnabled(enabled);
  view.needsRender = true;
};

// --- Drawing ---------------------------------------------------------------------------------

function drawScene() {
  axes.update(store, selected);
  robot.update(store);
  timeline.update(store);
  posePanel.update(store);
  treePanel.updateFlags(store);
  if (store.fixedFrame !== shownFixedFrame) updateFixedFrameChoices();
  stats.framesDrawn = store.poses.size;
  stats.fixedFrame = store.fixedFrame;
  stats.time = store.time;
  stats.live = store.live;
  stats.history = { ...store.history };
  $('hud-frames').textContent = `${store.poses.size} frames in ${store.fixedFrame || '?'}`;
  view.needsRender = true;
}

// Draws what changed (the last scene, the camera), then acks the scene.
function draw(now) {
  const drawnScene = sceneChanged;
  if (sceneChanged) {
    sceneChanged = false;
    drawScene();
  }
  // Until the user moves the camera, it frames everything whenever more frames or the
  // robot's meshes arrive.
  if (!view.userMovedCamera && store.poses.size > 0 &&
      (fitPending || store.poses.size > fittedFrames)) {
    fitPending = false;
    fittedFrames = store.poses.size;
    fitView();
  }
  if (view.needsRender) {
    const started = performance.now();
    view.render();
    stats.renderMs = stats.renderMs * 0.9 + (performance.now() - started) * 0.1;
    labels.update(store, view, selected);
    renderMeter.tick(now);
  }
  if (drawnScene && store.lastSceneFull && viewSentAt !== null) {
    stats.viewLatencyMs = performance.now() - viewSentAt;
    viewSentAt = null;
  }
  // The server sends the next scene once this one is drawn.
  if (pendingAck !== null) {
    connection.send({ type: 'ack', seq: pendingAck });
    pendingAck = null;
    stats.sceneCount = store.sceneCount;
    if (store.lastSceneFull) stats.fullSceneCount += 1;
  }
}

let hudShownAt = 0;
function animate(now) {
  frameMeter.tick(now);
  draw(now);
  stats.fps = frameMeter.fps;
  stats.rendersPerSecond = renderMeter.fps;
  if (now - hudShownAt >= 1000) {
    hudShownAt = now;
    hudFps.textContent = `${stats.fps} fps`;
  }
  requestAnimationFrame(animate);
}

connection.start();
requestAnimationFrame(animate);
