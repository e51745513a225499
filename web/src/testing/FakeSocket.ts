// A WebSocket for WsClient's tests: what the client sends is kept parsed in `sent`, what the
// server says is handed to `receive`. Tests whose close differs (dropped, or only noted)
// override close().
import type { SocketLike } from '../api/WsClient';

export class FakeSocket implements SocketLike {
    onopen: SocketLike['onopen'] = null;
    onmessage: SocketLike['onmessage'] = null;
    onclose: SocketLike['onclose'] = null;
    onerror: SocketLike['onerror'] = null;
    sent: Record<string, unknown>[] = [];
    send(data: string) { this.sent.push(JSON.parse(data)); }
    close() { this.onclose?.({}); }
    /** A message from the server: JSON text, or a binary frame as it is. */
    receive(msg: unknown) { this.onmessage?.({ data: msg instanceof ArrayBuffer ? msg : JSON.stringify(msg) }); }
}
