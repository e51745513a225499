// One live session of the open model (docs/live-sessions.md): live.start and the controls
// (pause, resume, step, speed, stop, record, set) over the editor's socket; each frame's
// latest value of every streamed variable by name; the session's state as the UI shows it.
// It ends cleanly whichever way the server ends it: a stopped event, an error reply, or the
// socket lost (a session lives and dies with its socket).
import type { WsClient } from '../api/WsClient';
import type {
    LiveEvent, LiveFrameEvent, LiveRecordedData, LiveSpeed, LiveStartedData, LiveStateData, LiveStateEvent, LiveValue,
} from '../protocol/types';
import { liveErrorText, stoppedText } from './liveErrors';

/** The socket calls the session needs (a fake one in tests). */
export interface LiveTransport {
    request: WsClient['request'];
    onLive: WsClient['onLive'];
    onStatus: WsClient['onStatus'];
}

/** idle: never started here; starting: live.start sent; stopped: it ended (message says why). */
export type LivePhase = 'idle' | 'starting' | 'running' | 'paused' | 'stopped';

export interface LiveStatus {
    phase: LivePhase;
    speed: LiveSpeed;
    /** Model seconds per wall second over the last second, as the server measured it. */
    achievedSpeed: number;
    /** The server says it cannot keep up with `speed` (achievedSpeed is below it). */
    behind: boolean;
    modelTime: number;
    /** Why it stopped, or the last refused request, in words; '' when all is well. */
    message: string;
    /** A notice that does not stop the session (the recording is full). */
    notice: string;
}

export type FrameListener = (values: ReadonlyMap<string, number>, frame: LiveFrameEvent) => void;

/**
 * The server ends a session after 10 minutes without a message from its owner
 * (--live-idle-timeout), to free what a forgotten tab holds; someone watching the drawing sends
 * nothing. While the page is shown, a ping this often keeps the session.
 */
export const KEEP_ALIVE_MS = 60_000;

/** Whether the user can see the page (always, where there is no document: tests, workers). */
const pageShown = () => typeof document === 'undefined' || document.visibilityState === 'visible';

/** Below this share of the asked speed the session counts as behind (the server's measure wobbles). */
const BEHIND_SHARE = 0.95;

export class LiveSession {
    status: LiveStatus = { phase: 'idle', speed: 1, achievedSpeed: 0, behind: false, modelTime: 0, message: '', notice: '' };
    /** The reply to live.start: the streamed variables, live_values, start/step/stop. */
    started: LiveStartedData | null = null;
    /** The latest value of each streamed variable. */
    readonly values = new Map<string, number>();
    /** The latest value sent for each live value (what its control shows). */
    readonly setValues = new Map<string, number>();
    private sessionId: number | null = null;
    /** Watching another's session (watch()): nothing here changes it. */
    watching = false;
    /** Events that came while live.start's reply had not (their session id was not known yet). */
    private early: LiveEvent[] = [];
    private readonly listeners = new Set<() => void>();
    private readonly frameListeners = new Set<FrameListener>();
    private readonly detach: (() => void)[];
    private keepAlive: ReturnType<typeof setInterval> | null = null;

    constructor(private readonly transport: LiveTransport) {
        this.detach = [
            transport.onLive((event) => this.onEvent(event)),
            transport.onStatus((status) => {
                if (status === 'reconnecting' || status === 'closed') this.lost();
            }),
        ];
    }

    dispose(): void {
        for (const d of this.detach) d();
        this.keepAliveWhileActive(false);
    }

    get active(): boolean { return this.status.phase === 'starting' || this.status.phase === 'running' || this.status.phase === 'paused'; }

    /** What live.set may change, by name (empty before a session started here). */
    get liveValues(): LiveValue[] { return this.started?.live_values ?? []; }

    /** Tells `listener` of every change of status. */
    subscribe(listener: () => void): () => void {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    /** Tells `listener` of every frame, with the latest values (the plots' and the drawing's seam). */
    onFrame(listener: FrameListener): () => void {
        this.frameListeners.add(listener);
        return () => this.frameListeners.delete(listener);
    }

    /** Starts a session of the stored model `modelId` streaming `variables`; false when refused (status.message says why). */
    async start(modelId: number, variables: string[], speed: LiveSpeed): Promise<boolean> {
        if (this.active) return false;
        this.watching = false;
        this.sessionId = null;
        this.started = null;
        this.early = [];
        this.values.clear();
        this.setValues.clear();
        this.update({ phase: 'starting', speed, achievedSpeed: 0, behind: false, modelTime: 0, message: '', notice: '' });
        try {
            const reply = await this.transport.request('live.start', { model_id: modelId, speed, variables, frames: 'json' });
            if (this.status.phase !== 'starting') {
                // the socket was lost while starting: the session is gone with it
                return false;
            }
            this.started = reply;
            this.sessionId = reply.session_id;
            for (const v of reply.live_values) this.setValues.set(v.name, v.value);
            this.update({ phase: 'running', modelTime: reply.start });
            const early = this.early;
            this.early = [];
            for (const event of early) this.onEvent(event);
            return true;
        } catch (e) {
            this.update({ phase: 'stopped', message: liveErrorText('Go live', e) });
            return false;
        }
    }

    /**
     * Watches session `sessionId` read-only (live.subscribe): one of the user's own, or one a
     * teacher shares with their class. Its frames and state come as a started session's do;
     * nothing here controls it. False when refused (status.message says why).
     */
    async watch(sessionId: number): Promise<boolean> {
        if (this.active) return false;
        this.watching = true;
        this.started = null;
        this.values.clear();
        this.setValues.clear();
        // its events are told apart by its id, known before the reply
        this.sessionId = sessionId;
        this.early = [];
        this.update({ phase: 'starting', achievedSpeed: 0, behind: false, modelTime: 0, message: '', notice: '' });
        try {
            const state = await this.transport.request('live.subscribe', { session_id: sessionId, frames: 'json' });
            // a stopped event (or the socket lost) may have come first: that stays
            if (this.status.phase !== 'starting') return false;
            this.update({ phase: state.state === 'stopped' ? 'stopped' : state.state, speed: state.speed, modelTime: state.model_time });
            return true;
        } catch (e) {
            this.sessionId = null;
            this.update({ phase: 'stopped', message: liveErrorText('Watch', e) });
            return false;
        }
    }

    pause(): Promise<void> { return this.control('Pause', 'live.pause'); }
    resume(): Promise<void> { return this.control('Resume', 'live.resume'); }
    stop(): Promise<void> { return this.control('Stop', 'live.stop'); }

    /** Runs a paused session `steps` time steps (the server sends their frame). */
    async step(steps: number): Promise<void> {
        const id = this.sessionId;
        if (id === null) return;
        await this.apply('Step', () => this.transport.request('live.step', { session_id: id, steps }));
    }

    async setSpeed(speed: LiveSpeed): Promise<void> {
        const id = this.sessionId;
        if (id === null) {
            this.update({ speed });
            return;
        }
        await this.apply('Speed', () => this.transport.request('live.speed', { session_id: id, speed }));
    }

    /**
     * Sends a new value of a live value; the server applies sets of one name at most 100 times
     * a second (the last wins), so a slider may send every movement. False when refused.
     */
    async set(name: string, value: number): Promise<boolean> {
        const id = this.sessionId;
        if (id === null || !this.active || this.watching) return false;
        this.setValues.set(name, value);
        try {
            await this.transport.request('live.set', { session_id: id, name, value });
            return true;
        } catch (e) {
            this.fail(`Set ${name}`, e);
            return false;
        }
    }

    /** Lets the members of class `classId` watch the session (live.share); false when refused. */
    async share(classId: number): Promise<boolean> {
        const id = this.sessionId;
        if (id === null || this.watching) return false;
        try {
            await this.transport.request('live.share', { session_id: id, class_id: classId });
            return true;
        } catch (e) {
            this.fail('Share with class', e);
            return false;
        }
    }

    /** Stores what the session ran so far as a run of the model's history; null when refused. */
    async record(): Promise<LiveRecordedData | null> {
        const id = this.sessionId;
        if (id === null) return null;
        try {
            return await this.transport.request('live.record', { session_id: id });
        } catch (e) {
            this.fail('Keep as a run', e);
            return null;
        }
    }

    private async control(what: string, type: 'live.pause' | 'live.resume' | 'live.stop'): Promise<void> {
        const id = this.sessionId;
        if (id === null) return;
        await this.apply(what, () => this.transport.request(type, { session_id: id }));
    }

    /** Sends a control and shows the state its reply gives. */
    private async apply(what: string, send: () => Promise<LiveStateData>): Promise<void> {
        try {
            const state = await send();
            // the stopped event may come before the reply: it said why, and that stays
            if (this.status.phase === 'stopped') return;
            if (state.state === 'stopped') {
                this.sessionId = null;
                this.update({ phase: 'stopped', speed: state.speed, modelTime: state.model_time, behind: false,
                    message: stoppedText({ reason: 'requested', model_time: state.model_time }) });
                return;
            }
            this.update({ phase: state.state, speed: state.speed, modelTime: state.model_time, message: '' });
        } catch (e) {
            this.fail(what, e);
        }
    }

    /** A refused request: the message says what; a session the server no longer has has ended. */
    private fail(what: string, e: unknown): void {
        const gone = (e as { code?: string }).code;
        const ended = gone === 'not_found' || gone === 'not_connected' || gone === 'connection_lost';
        this.update(ended ? { phase: 'stopped', message: liveErrorText(what, e) } : { message: liveErrorText(what, e) });
        if (ended) this.sessionId = null;
    }

    private onEvent(event: LiveEvent): void {
        if (this.status.phase === 'starting' && this.sessionId === null) {
            this.early.push(event);
            return;
        }
        if (event.session_id !== this.sessionId) return;
        if (event.type === 'event.live.frame') this.onFrameEvent(event);
        else this.onState(event);
    }

    private onFrameEvent(frame: LiveFrameEvent): void {
        for (const [name, samples] of Object.entries(frame.variables)) {
            if (samples.length > 0) this.values.set(name, samples[samples.length - 1]);
        }
        this.status = { ...this.status, modelTime: frame.model_time };
        for (const l of this.frameListeners) l(this.values, frame);
    }

    private onState(event: LiveStateEvent): void {
        if (event.reason === 'record_limit') {
            this.update({ notice: `The recording is full${event.message ? ` (${event.message})` : ''}: "Keep as run" keeps its first part.` });
            return;
        }
        const speed = event.speed;
        // (0 is what a session just started or resumed reports: nothing measured yet)
        const behind = event.state === 'running' && typeof speed === 'number' && event.achieved_speed > 0 && event.achieved_speed < speed * BEHIND_SHARE;
        if (event.state === 'stopped') {
            this.sessionId = null;
            this.update({ phase: 'stopped', speed, achievedSpeed: 0, behind: false, modelTime: event.model_time, message: stoppedText(event) });
            return;
        }
        this.update({ phase: event.state, speed, achievedSpeed: event.achieved_speed, behind, modelTime: event.model_time });
    }

    /** The socket is gone, and every session of it with it. */
    private lost(): void {
        if (!this.active) return;
        this.sessionId = null;
        this.update({ phase: 'stopped', behind: false, message: 'The connection to the server was lost, and the live session with it. Go live again once connected.' });
    }

    private update(changes: Partial<LiveStatus>): void {
        this.status = { ...this.status, ...changes };
        this.keepAliveWhileActive(this.active && !this.watching);
        for (const l of this.listeners) l();
    }

    /** Pings while a session of this page's runs and the page is shown (KEEP_ALIVE_MS). */
    private keepAliveWhileActive(on: boolean): void {
        if (on && !this.keepAlive) {
            this.keepAlive = setInterval(() => {
                if (pageShown()) this.transport.request('ping', {}).catch(() => undefined);
            }, KEEP_ALIVE_MS);
        } else if (!on && this.keepAlive) {
            clearInterval(this.keepAlive);
            this.keepAlive = null;
        }
    }
}
