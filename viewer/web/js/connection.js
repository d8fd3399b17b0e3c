// The page's one WebSocket to the viewer: JSON messages in and out, and reconnection with
// backoff when the socket closes. The protocol is written down in viewer/protocol.md.

const FIRST_RETRY_MS = 500;
const LAST_RETRY_MS = 8000;

export class Connection {
  // onMessage(msg) gets each parsed message; onState(state, detail) gets 'connecting', 'open',
  // 'reconnecting' (detail: {inMs, reason}).
  constructor(url, { onMessage, onState }) {
    this.url = url;
    this.onMessage = onMessage;
    this.onState = onState;
    this.socket = null;
    this.retries = 0;
    this.retryTimer = null;
  }

  start() {
    this.open();
  }

  get isOpen() {
    return this.socket !== null && this.socket.readyState === WebSocket.OPEN;
  }

  // Sends one message; false when there is no open socket (the message is dropped: everything
  // the page sends is state that it sends again after reconnecting).
  send(message) {
    if (!this.isOpen) return false;
    this.socket.send(JSON.stringify(message));
    return true;
  }

  open() {
    this.retryTimer = null;
    this.onState('connecting', {});
    let socket;
    try {
      socket = new WebSocket(this.url);
    } catch (error) {
      this.scheduleRetry(String(error));
      return;
    }
    this.socket = socket;
    socket.onopen = () => {
      this.retries = 0;
      this.onState('open', {});
    };
    socket.onmessage = (event) => {
      if (typeof event.data !== 'string') return;
      let message;
      try {
        message = JSON.parse(event.data);
      } catch (error) {
        console.warn('lcmtf viewer: a message that is not JSON', error);
        return;
      }
      if (message === null || typeof message !== 'object') return;
      this.onMessage(message);
    };
    socket.onclose = (event) => {
      if (this.socket !== socket) return;
      this.socket = null;
      const reason = event.reason ? `${event.code} ${event.reason}` : `code ${event.code}`;
      this.scheduleRetry(reason);
    };
    // An error is always followed by close, which retries.
    socket.onerror = () => {};
  }

  scheduleRetry(reason) {
    const inMs = Math.min(LAST_RETRY_MS, FIRST_RETRY_MS * 2 ** this.retries);
    this.retries += 1;
    this.onState('reconnecting', { inMs, reason });
    this.retryTimer = setTimeout(() => this.open(), inMs);
  }
}
