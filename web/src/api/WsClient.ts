// WebSocket client for tlmhub.v1: numbered requests answered by promises, events to listeners.
import { ApiError } from './ApiError';
import { decodeBinaryFrame } from './binaryFrame';
import type { HelloMessage, ServerEvent, ServerMessage } from '../protocol/types';
import type { ReplyData, RequestFields, RequestType } from '../protocol/requests.generated';

/** The part of the browser WebSocket the client uses (a fake one in tests). */
export interface SocketLike {
    onopen: ((ev: unknown) => void) | null;
    onmessage: ((ev: { data: unknown }) => void) | null;
    onclose: ((ev: unknown) => void) | null;
    onerror: ((ev: unknown) => void) | null;
    send(data: string): void;
    close(): void;
}

type EventListener = (event: ServerEvent) => void;

interface Pending { resolve: (data: unknown) => void; reject: (e: Error) => void }

/** A request's fields, which may be left out when the request has none that are required. */
type FieldsArgument<T extends RequestType> = {} extends RequestFields<T> ? [fields?: RequestFields<T>] : [fields: RequestFields<T>];

export class WsClient {
    private socket: SocketLike | null = null;
    private nextId = 1;
    private readonly pending = new Map<number | string, Pending>();
    private readonly listeners = new Set<EventListener>();
    private closeListeners = new Set<(reason: string) => void>();
    hello: HelloMessage | null = null;

    constructor(private readonly open: () => SocketLike) {}

    /** Opens the socket and resolves with the server's hello message. */
    connect(): Promise<HelloMessage> {
        return new Promise((resolve, reject) => {
            const socket = this.open();
            this.socket = socket;
            let greeted = false;
            socket.onmessage = (ev) => {
                const msg = parse(ev.data);
                if (!msg) return;
                if (msg.type === 'hello') {
                    greeted = true;
                    this.hello = msg;
                    resolve(msg);
                    return;
                }
                this.dispatch(msg);
            };
            socket.onerror = () => { if (!greeted) reject(new ApiError('ws_error', 'WebSocket connection failed')); };
            socket.onclose = () => {
                this.socket = null;
                if (!greeted) reject(new ApiError('ws_closed', 'WebSocket closed before hello'));
                this.failAll('connection closed');
                for (const l of this.closeListeners) l('closed');
            };
        });
    }

    get connected(): boolean { return this.socket !== null && this.hello !== null; }

    /** Sends one request; resolves with the reply's data or rejects with the error reply. */
    request<T extends RequestType>(type: T, ...[fields]: FieldsArgument<T>): Promise<ReplyData<T>> {
        if (!this.socket) return Promise.reject(new ApiError('not_connected', 'not connected to the server'));
        const id = this.nextId++;
        const message = { ...fields, id, type };
        return new Promise<ReplyData<T>>((resolve, reject) => {
            // The server sends the data x-replies defines for the request's type (its tests check it).
            this.pending.set(id, { resolve: (data) => resolve(data as ReplyData<T>), reject });
            this.socket!.send(JSON.stringify(message));
        });
    }

    /** Listens to events (event.progress, event.frame, event.done, event.resync); returns the unsubscriber. */
    onEvent(listener: EventListener): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    onClose(listener: (reason: string) => void): () => void {
        this.closeListeners.add(listener);
        return () => this.closeListeners.delete(listener);
    }

    close(): void {
        this.closeListeners = new Set();
        this.socket?.close();
        this.socket = null;
        this.failAll('connection closed');
    }

    private dispatch(msg: ServerMessage): void {
        if (msg.type === 'reply') {
            const waiter = this.pending.get(msg.id);
            if (!waiter) return;
            this.pending.delete(msg.id);
            waiter.resolve(msg.data ?? {});
        } else if (msg.type === 'error') {
            const waiter = msg.id === null ? undefined : this.pending.get(msg.id);
            if (waiter && msg.id !== null) {
                this.pending.delete(msg.id);
                waiter.reject(new ApiError(msg.error.code, msg.error.message));
            } else {
                console.warn('tlmhub: server error without request', msg.error);
            }
        } else if (msg.type.startsWith('event.')) {
            for (const l of this.listeners) l(msg as ServerEvent);
        }
    }

    private failAll(reason: string): void {
        for (const waiter of this.pending.values()) waiter.reject(new ApiError('not_connected', reason));
        this.pending.clear();
    }
}

function parse(data: unknown): ServerMessage | null {
    if (data instanceof ArrayBuffer) return decodeBinaryFrame(data);
    if (typeof data !== 'string') return null;
    try {
        const msg: unknown = JSON.parse(data);
        const ok = typeof msg === 'object' && msg !== null && typeof (msg as { type?: unknown }).type === 'string';
        return ok ? (msg as ServerMessage) : null;
    } catch {
        return null;
    }
}

/** The app's WebSocket URL for a token, relative to the page. */
export function socketUrl(token: string, location: { protocol: string; host: string }): string {
    const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
    return `${scheme}//${location.host}/api/v1/ws?token=${encodeURIComponent(token)}`;
}
