// Figures about the page that tests and benchmarks read from window.lcmtfViewer instead of
// scraping the page.

// Animation frames over the last second.
export class FpsMeter {
  constructor() {
    this.stamps = [];
  }

  tick(now) {
    this.stamps.push(now);
    while (this.stamps.length > 0 && this.stamps[0] <= now - 1000) this.stamps.shift();
  }

  get fps() {
    return this.stamps.length;
  }
}

// The object published as window.lcmtfViewer; main.js keeps its fields current.
export function createPageStats() {
  const stats = {
    connection: 'connecting', // 'connecting', 'open' or 'reconnecting'
    serverVersion: null,
    framesDrawn: 0, // frames with a pose in the last scene
    framesListed: 0, // frames in the tree panel
    sceneCount: 0, // scenes drawn since the page opened
    fullSceneCount: 0,
    fps: 0, // animation frames over the last second
    rendersPerSecond: 0, // of which the 3D view was drawn again
    renderMs: 0, // the time a drawing of the 3D view takes (moving average)
    robotLoaded: false, // a robot description is drawn
    robotName: null,
    meshesLoaded: 0,
    meshesFailed: 0,
    meshesPending: 0,
    warnings: [], // as the panel lists them
    errors: [], // the last messages the server refused
    fixedFrame: null,
    time: 0, // the stamp drawn
    live: true,
    history: { oldest: 0, newest: 0 },
    jointsPublishing: false,
    viewLatencyMs: null, // from sending the last `view` to drawing its first scene
    selected: null,
  };
  return stats;
}
