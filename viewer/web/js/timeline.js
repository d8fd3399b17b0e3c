// The time bar: play/pause, a slider over the buffer's history, and the time drawn.

// HH:MM:SS.mmm (local time) of an LCM time in microseconds.
export function formatClock(utime) {
  const date = new Date(utime / 1000);
  const two = (n) => String(n).padStart(2, '0');
  return `${two(date.getHours())}:${two(date.getMinutes())}:${two(date.getSeconds())}.` +
    String(date.getMilliseconds()).padStart(3, '0');
}

export class Timeline {
  // onPlay() asks for live drawing; onPause(time) and onScrub(time) for drawing at `time`
  // (onScrub while the slider is dragged, throttled by the caller).
  constructor({ button, slider, label, onPlay, onPause, onScrub }) {
    this.button = button;
    this.slider = slider;
    this.label = label;
    this.onPlay = onPlay;
    this.onPause = onPause;
    this.onScrub = onScrub;
    this.paused = false;
    this.dragging = false;
    this.drawnTime = 0;

    button.addEventListener('click', () => {
      if (this.paused) {
        this.setPaused(false);
        this.onPlay();
      } else if (this.drawnTime > 0) {
        this.setPaused(true);
        this.onPause(this.drawnTime);
      }
    });
    slider.addEventListener('pointerdown', () => { this.dragging = true; });
    window.addEventListener('pointerup', () => { this.dragging = false; });
    slider.addEventListener('input', () => {
      const time = Math.round(Number(slider.value));
      if (!Number.isFinite(time) || time <= 0) return;
      if (!this.paused) this.setPaused(true);
      this.onScrub(time);
    });
  }

  setPaused(paused) {
    this.paused = paused;
    this.button.textContent = paused ? 'Play' : 'Pause';
    this.button.title = paused ? 'Follow the newest data' : 'Pause to scrub back through the history';
  }

  // Follows the last scene: the slider spans its history, the label says what is drawn.
  update(store) {
    const { oldest, newest } = store.history;
    this.drawnTime = store.time;
    const known = newest > 0;
    this.slider.disabled = !known || newest <= oldest;
    if (known) {
      this.slider.min = String(oldest);
      this.slider.max = String(Math.max(newest, oldest + 1));
      if (!this.dragging) this.slider.value = String(store.live ? newest : store.time);
    }
    let text;
    if (!known || store.time <= 0) {
      text = 'waiting for data';
    } else if (store.live) {
      text = `live · ${formatClock(store.time)}`;
    } else {
      const ago = Math.max(0, (newest - store.time) / 1e6);
      text = `paused, ${ago.toFixed(1)} s ago · ${formatClock(store.time)}`;
      // The buffer has let go of that time: frames moved by then are no longer drawn.
      if (store.time < oldest) text += ' (older than the history)';
    }
    if (this.label.textContent !== text) this.label.textContent = text;
    this.label.classList.toggle('paused', known && !store.live);
  }
}
