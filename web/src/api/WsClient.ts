// WebSocket client for tlmhub.v1: numbered requests answered by promises, events to listeners.
// When the socket closes unexpectedly it reconnects (exponential backoff with full jitter),
// subscribes again to the jobs whose event.done had not come, and lets the page restore the
// rest of its per-socket state (the open model) through onReconnect.
import { ApiError } from './ApiError';
import { decodeBinaryFrame } from './binaryFrame';
import type { HelloMessage, LiveEvent, ServerEvent, ServerMessage } from '../protocol/types';
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

interface Pending { type: string; resolve: (data: unknown) => void; reject: (e: Error) => void }

/** A request's fields, which may be left out when the request has none that are required. */
type FieldsArgument<T extends RequestType> = {} extends RequestFields<T> ? [fields?: RequestFields<T>] : [fields: RequestFields<T>];

/**
 * connecting: the first connection; connected: greeted (and, after a reconnect, restored);
 * reconnecting: the socket was lost and the client tries again; closed: closed on purpose, or
 * the server ended the login (`reason` of onClose is then 'auth'), or the first connection failed.
 */
export type ConnectionStatus = 'connecting' | 'connected' | 'reconnecting' | 'closed';

export interface ReconnectOptions {
    /** false: no reconnecting (the old behaviour). */
    enabled: boolean;
    /** First delay's upper bound, doubled per failed attempt up to maxDelayMs (full jitter). */
    baseDelayMs: number;
    maxDelayMs: number;
    /** A connection that stayed up this long starts the backoff over. */
    stableMs: number;
    /** Uniform in [0, 1); Math.random by default. */
    random: () => number;
    setTimer: (fn: () => void, ms: number) => unknown;
    clearTimer: (handle: unknown) => void;
    now: () => number;
    /**
     * Asked before each reconnect attempt; false stops reconnecting (e.g. the login ended,
     * which a failed upgrade does not tell the browser). Errors count as true. Without it a
     * close with code 1008 (the login ended, or the role changed) stops reconnecting; with it,
     * it decides (a role change reconnects with the new role).
     */
    shouldReconnect?: () => boolean | Promise<boolean>;
}

export const defaultReconnect: ReconnectOptions = {
    enabled: true,
    baseDelayMs: 250,
    maxDelayMs: 10_000,
    stableMs: 5_000,
    random: Math.random,
    setTimer: (fn, ms) => setTimeout(fn, ms),
    clearTimer: (handle) => clearTimeout(handle as ReturnType<typeof setTimeout>),
    now: () => Date.now(),
};

/** The delay before reconnect attempt `attempt` (0, 1, ...): full jitter over a capped doubling. */
export function backoffDelay(attempt: number, random: () => number, baseMs = 250, maxMs = 10_000): number {
    const ceiling = Math.min(maxMs, baseMs * 2 ** Math.min(attempt, 30));
    return Math.floor(random() * ceiling);
}

/** A job this socket streams: subscribed again, with the same fields, after a reconnect. */
interface JobSubscription { job_id: number; variables?: string[]; rate?: number; frames?: 'json' | 'binary' }

/**
 * Requests whose reply is a whole model: the server builds at most two of a user's large
 * replies at once and refuses more with 'busy' (SECURITY.md). They only read, so they are sent
 * again a second later, a few times, before the caller sees the refusal.
 */
const RETRIED_WHEN_BUSY: ReadonlySet<string> = new Set(['model.open', 'model.get']);
const BUSY_RETRIES = 5;
const BUSY_RETRY_MS = 1000;

/** The close code the server uses when the login ends (logout, expiry, password or role change). */
const POLICY_CLOSE = 1008;

export class WsClient {
    private socket: SocketLike | null = null;
    private nextId = 1;
    private readonly pending = new Map<number | string, Pending>();
    private readonly listeners = new Set<EventListener>();
    private readonly liveListeners = new Set<(event: LiveEvent) => void>();
    private closeListeners = new Set<(reason: string) => void>();
    private readonly statusListeners = new Set<(status: ConnectionStatus) => void>();
    private readonly reconnectListeners = new Set<() => Promise<unknown> | void>();
    private readonly resubscribeListeners = new Set<(jobId: number) => void>();
    private readonly subscriptions = new Map<number, JobSubscription>();
    private readonly options: ReconnectOptions;
    private intentional = false;
    private attempt = 0;
    private timer: unknown = null;
    private greetedAt = 0;
    private everConnected = false;
    status: ConnectionStatus = 'connecting';
    hello: HelloMessage | null = null;

    constructor(private readonly open: () => SocketLike, options: Partial<ReconnectOptions> = {}) {
        this.options = { ...defaultReconnect, ...options };
    }

    /** Opens the socket and resolves with the server's hello message. */
    connect(): Promise<HelloMessage> {
        this.intentional = false;
        return this.openSocket();
    }

    private openSocket(): Promise<HelloMessage> {
        return new Promise((resolve, reject) => {
            const socket = this.open();
            this.socket = socket;
            let greeted = false;
            socket.onmessage = (ev) => {
                if (this.socket !== socket) return;
                const msg = parse(ev.data);
                if (!msg) return;
                if (msg.type === 'hello') {
                    greeted = true;
                    this.hello = msg;
                    this.greetedAt = this.options.now();
                    if (!this.everConnected) {
                        this.everConnected = true;
                        this.setStatus('connected');
                    }
                    resolve(msg);
                    return;
                }
                this.dispatch(msg);
            };
            socket.onerror = () => { if (!greeted) reject(new ApiError('ws_error', 'WebSocket connection failed')); };
            socket.onclose = (ev) => {
                if (this.socket !== socket) return;   // an old socket, already given up
                this.socket = null;
                this.hello = null;
                if (!greeted) reject(new ApiError('ws_closed', 'WebSocket closed before hello'));
                this.onSocketClosed(greeted, (ev as { code?: number } | null)?.code);
            };
        });
    }

    get connected(): boolean { return this.socket !== null && this.hello !== null && this.status === 'connected'; }

    /** Sends one request; resolves with the reply's data or rejects with the error reply. */
    request<T extends RequestType>(type: T, ...[fields]: FieldsArgument<T>): Promise<ReplyData<T>> {
        if (!this.socket || !this.hello) {
            const why = this.status === 'reconnecting' ? 'the connection to the server was lost; reconnecting' : 'not connected to the server';
            return Promise.reject(new ApiError('not_connected', why));
        }
        if (RETRIED_WHEN_BUSY.has(type)) return this.sendRetryingWhenBusy(type, fields);
        return this.send(type, fields);
    }

    private async sendRetryingWhenBusy<T extends RequestType>(type: T, fields: RequestFields<T> | undefined): Promise<ReplyData<T>> {
        for (let attempt = 0; ; ++attempt) {
            try {
                return await this.send(type, fields);
            } catch (e) {
                if (!(e instanceof ApiError) || e.code !== 'busy' || attempt >= BUSY_RETRIES) throw e;
                await new Promise<void>((resolve) => { this.options.setTimer(resolve, BUSY_RETRY_MS); });
            }
        }
    }

    private send<T extends RequestType>(type: T, fields: RequestFields<T> | undefined): Promise<ReplyData<T>> {
        if (!this.socket) return Promise.reject(new ApiError('connection_lost', `${type}: the connection to the server was lost`));
        const id = this.nextId++;
        const message = { ...fields, id, type };
        return new Promise<ReplyData<T>>((resolve, reject) => {
            // The server sends the data x-replies defines for the request's type (its tests check it).
            this.pending.set(id, {
                type,
                resolve: (data) => {
                    this.track(type, fields, data);
                    resolve(data as ReplyData<T>);
                },
                reject,
            });
            this.socket!.send(JSON.stringify(message));
        });
    }

    /** Remembers the job subscriptions of simulate.start and log.subscribe until their event.done. */
    private track(type: string, fields: unknown, data: unknown): void {
        const f = (fields ?? {}) as Partial<JobSubscription>;
        const jobId = type === 'simulate.start' ? (data as { job_id?: number }).job_id
            : type === 'log.subscribe' ? f.job_id : undefined;
        if (typeof jobId !== 'number' || this.finishedEarly.has(jobId)) return;
        const sub: JobSubscription = { job_id: jobId };
        if (f.variables) sub.variables = [...f.variables];
        if (f.rate !== undefined) sub.rate = f.rate;
        if (f.frames !== undefined) sub.frames = f.frames;
        this.subscriptions.set(jobId, sub);
    }

    /** Jobs whose event.done came (it may overtake the reply that started their subscription). */
    private readonly finishedEarly = new Set<number>();

    /** Jobs streamed to this client whose event.done has not come (what a reconnect resubscribes). */
    get activeSubscriptions(): number[] { return [...this.subscriptions.keys()]; }

    /** Listens to events (event.progress, event.frame, event.done, event.resync); returns the unsubscriber. */
    onEvent(listener: EventListener): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    /**
     * Listens to live sessions' events (event.live.frame, event.live.state); returns the
     * unsubscriber. A session ends with the socket that started it: a reconnect (onStatus
     * 'reconnecting') means every session of this client is gone, with no event to say so.
     */
    onLive(listener: (event: LiveEvent) => void): () => void {
        this.liveListeners.add(listener);
        return () => this.liveListeners.delete(listener);
    }

    /** The socket closed and the client does not reconnect: 'auth' (the server ended the login) or 'closed'. */
    onClose(listener: (reason: string) => void): () => void {
        this.closeListeners.add(listener);
        return () => this.closeListeners.delete(listener);
    }

    onStatus(listener: (status: ConnectionStatus) => void): () => void {
        this.statusListeners.add(listener);
        return () => this.statusListeners.delete(listener);
    }

    /**
     * Runs after a reconnect's hello, once the jobs are subscribed again and before the status
     * is 'connected': restores the rest of the socket's state (model.open). Errors are logged.
     */
    onReconnect(listener: () => Promise<unknown> | void): () => void {
        this.reconnectListeners.add(listener);
        return () => this.reconnectListeners.delete(listener);
    }

    /**
     * Told just before log.subscribe is sent again for a job: its frames start over at sample 0
     * (and seq 0), so the listener drops the samples it already has (RunData.restartStream).
     */
    onResubscribe(listener: (jobId: number) => void): () => void {
        this.resubscribeListeners.add(listener);
        return () => this.resubscribeListeners.delete(listener);
    }

    /** Closes on purpose (leaving the page, logging out): no reconnecting. */
    close(): void {
        this.intentional = true;
        this.closeListeners = new Set();
        if (this.timer !== null) this.options.clearTimer(this.timer);
        this.timer = null;
        const socket = this.socket;
        this.socket = null;
        socket?.close();
        this.failAll('connection closed');
        this.setStatus('closed');
    }

    /** Test hook (e2e builds): drops the socket as a lost connection would, so the client reconnects. */
    dropForTest(): void {
        const socket = this.socket;
        if (!socket) return;
        this.socket = null;
        this.hello = null;
        socket.onclose = null;
        socket.onmessage = null;
        socket.close();
        this.onSocketClosed(true, 1006);
    }

    private onSocketClosed(greeted: boolean, code: number | undefined): void {
        this.failAll('the connection to the server was lost before the reply came');
        if (this.intentional) return;
        const loginCheck = this.options.shouldReconnect !== undefined;
        const mayReconnect = this.options.enabled && this.everConnected && (code !== POLICY_CLOSE || loginCheck);
        if (!mayReconnect) {
            this.setStatus('closed');
            for (const l of this.closeListeners) l(code === POLICY_CLOSE ? 'auth' : 'closed');
            return;
        }
        if (greeted && this.options.now() - this.greetedAt >= this.options.stableMs) this.attempt = 0;
        if (code === POLICY_CLOSE) this.attempt = 0;   // the login check decides at once
        this.setStatus('reconnecting');
        this.schedule();
    }

    private schedule(): void {
        const delay = backoffDelay(this.attempt, this.options.random, this.options.baseDelayMs, this.options.maxDelayMs);
        this.attempt += 1;
        this.timer = this.options.setTimer(() => {
            this.timer = null;
            void this.reconnect();
        }, delay);
    }

    private async reconnect(): Promise<void> {
        if (this.intentional) return;
        let go = true;
        try {
            go = await (this.options.shouldReconnect?.() ?? true);
        } catch {
            go = true;
        }
        if (this.intentional) return;
        if (!go) {
            this.setStatus('closed');
            for (const l of this.closeListeners) l('auth');
            return;
        }
        try {
            await this.openSocket();
        } catch {
            return;   // onclose scheduled the next attempt
        }
        await this.restore();
    }

    /** After a reconnect's hello: subscribes again to the unfinished jobs, then the page's listeners. */
    private async restore(): Promise<void> {
        const subscribed = [...this.subscriptions.values()].map((sub) => {
            for (const l of this.resubscribeListeners) l(sub.job_id);
            const { job_id, ...rest } = sub;
            return this.send('log.subscribe', { job_id, ...rest }).catch((e: unknown) => {
                // the job is gone (deleted) or not the user's: nothing more will come for it
                // (a socket lost again before the reply keeps it for the next attempt)
                const lost = e instanceof ApiError && (e.code === 'not_connected' || e.code === 'connection_lost');
                if (!lost) this.subscriptions.delete(job_id);
                console.warn(`tlmhub: subscribing again to job ${job_id} failed`, e);
            });
        });
        const restored = [...this.reconnectListeners].map(async (l) => {
            try {
                await l();
            } catch (e) {
                console.warn('tlmhub: restoring the connection\'s state failed', e);
            }
        });
        await Promise.all([...subscribed, ...restored]);
        if (this.socket && this.hello && !this.intentional) this.setStatus('connected');
    }

    private setStatus(status: ConnectionStatus): void {
        if (this.status === status) return;
        this.status = status;
        for (const l of this.statusListeners) l(status);
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
        } else if (msg.type === 'event.live.frame' || msg.type === 'event.live.state') {
            for (const l of this.liveListeners) l(msg);
        } else if (msg.type.startsWith('event.')) {
            if (msg.type === 'event.done') {
                const jobId = (msg as { job_id: number }).job_id;
                this.subscriptions.delete(jobId);
                this.rememberFinished(jobId);
            }
            for (const l of this.listeners) l(msg as ServerEvent);
        }
    }

    private rememberFinished(jobId: number): void {
        this.finishedEarly.add(jobId);
        if (this.finishedEarly.size > 64) this.finishedEarly.delete(this.finishedEarly.values().next().value!);
    }

    private failAll(reason: string): void {
        for (const waiter of this.pending.values()) waiter.reject(new ApiError('connection_lost', `${waiter.type}: ${reason}`));
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
