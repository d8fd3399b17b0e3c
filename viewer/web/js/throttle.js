// Calls fn at most once per intervalMs: the first call at once, later ones with the latest
// arguments at the end of the interval, so the last value is never lost.
export function throttle(fn, intervalMs) {
  let lastCall = -Infinity;
  let timer = null;
  let pendingArgs = null;

  const fire = () => {
    timer = null;
    lastCall = performance.now();
    const args = pendingArgs;
    pendingArgs = null;
    fn(...args);
  };

  const throttled = (...args) => {
    pendingArgs = args;
    if (timer !== null) return;
    const wait = lastCall + intervalMs - performance.now();
    if (wait <= 0) {
      fire();
    } else {
      timer = setTimeout(fire, wait);
    }
  };
  // Sends what is waiting now instead of at the end of the interval.
  throttled.flush = () => {
    if (timer === null) return;
    clearTimeout(timer);
    fire();
  };
  // Drops what is waiting.
  throttled.cancel = () => {
    if (timer !== null) clearTimeout(timer);
    timer = null;
    pendingArgs = null;
  };
  return throttled;
}
