import { describe, expect, it, vi } from 'vitest';
import { WsClient } from '../api/WsClient';
import { FakeSocket as SharedFakeSocket } from '../testing/FakeSocket';
import { KEEP_ALIVE_MS, LiveSession } from './LiveSession';

// The real WsClient over a fake socket, as the WsClient tests do: what the session sends is
// read from the socket, what the server says is received on it.
class FakeSocket extends SharedFakeSocket {
    override close() { this.onclose?.({ code: 1006 }); }
    last(type: string) { return [...this.sent].reverse().find((m) => m.type === type)!; }
    reply(type: string, data: unknown) { this.receive({ id: this.last(type).id, type: 'reply', ok: true, data }); }
    refuse(type: string, code: string, message: string) { this.receive({ id: this.last(type).id, type: 'error', error: { code, message } }); }
}

const hello = { type: 'hello', protocol: 'tlmhub.v1', user: { id: 1, username: 'alice', role: 'user' } };
const started = {
    session_id: 3, variables: ['Step#out#Value', 'Mass#P1#x'],
    live_values: [{ name: 'Step.y_A', value: 0.1, unit: '' }], start: 0, step: 0.0001, stop: 10,
};
const frame = (model_time: number, step: number[], x: number[], session_id = 3) => ({
    type: 'event.live.frame', session_id, model_time, wall_time: model_time, seq: 0, dropped: 0,
    time: step.map((_, i) => model_time - (step.length - 1 - i) * 0.01), variables: { 'Step#out#Value': step, 'Mass#P1#x': x },
});
const state = (fields: Record<string, unknown>) => ({ type: 'event.live.state', session_id: 3, state: 'running', speed: 1, achieved_speed: 1, model_time: 0, ...fields });

async function setup(reconnect = false) {
    const socket = new FakeSocket();
    const client = new WsClient(() => socket, { enabled: reconnect, setTimer: () => 0, clearTimer: () => undefined });
    const ready = client.connect();
    socket.receive(hello);
    await ready;
    const session = new LiveSession({ request: client.request.bind(client), onLive: client.onLive.bind(client), onStatus: client.onStatus.bind(client) });
    return { socket, client, session };
}

async function live(reconnect = false) {
    const h = await setup(reconnect);
    const going = h.session.start(12, ['Step#out#Value', 'Mass#P1#x'], 1);
    h.socket.reply('live.start', started);
    expect(await going).toBe(true);
    return h;
}

describe('LiveSession', () => {
    it('pings while its session runs, so watching without touching does not reach the idle timeout; not once stopped', async () => {
        vi.useFakeTimers();
        try {
            const { socket, session } = await live();
            const pings = () => socket.sent.filter((m) => m.type === 'ping').length;
            expect(pings()).toBe(0);
            vi.advanceTimersByTime(KEEP_ALIVE_MS * 3);
            expect(pings()).toBe(3);
            const stopping = session.stop();
            socket.reply('live.stop', { session_id: 3, state: 'stopped', speed: 1, achieved_speed: 0, model_time: 1 });
            await stopping;
            expect(session.status.phase).toBe('stopped');
            vi.advanceTimersByTime(KEEP_ALIVE_MS * 3);
            expect(pings()).toBe(3);
        } finally {
            vi.useRealTimers();
        }
    });

    it('starts with the model, the variables and the speed, and knows what live.set may change', async () => {
        const { socket, session } = await live();
        expect(socket.last('live.start')).toMatchObject({ model_id: 12, variables: ['Step#out#Value', 'Mass#P1#x'], speed: 1 });
        expect(session.status.phase).toBe('running');
        expect(session.liveValues.map((v) => v.name)).toEqual(['Step.y_A']);
        expect(session.setValues.get('Step.y_A')).toBe(0.1);
    });

    it('keeps the latest value of each variable by name, and tells the frame listeners', async () => {
        const { socket, session } = await live();
        const heard: number[] = [];
        session.onFrame((values) => heard.push(values.get('Mass#P1#x')!));
        socket.receive(frame(0.5, [0, 0.1], [0.001, 0.002]));
        socket.receive(frame(0.6, [0.1], [0.004]));
        expect(session.values.get('Step#out#Value')).toBe(0.1);
        expect(session.values.get('Mass#P1#x')).toBe(0.004);
        expect(heard).toEqual([0.002, 0.004]);
        expect(session.status.modelTime).toBe(0.6);
        // another session's frame (a second tab of the same user) is not this one's
        socket.receive(frame(0.7, [9], [9], 4));
        expect(session.values.get('Mass#P1#x')).toBe(0.004);
    });

    it('applies the events that came before the reply to live.start, once it names the session', async () => {
        const { socket, session } = await setup();
        const going = session.start(12, [], 1);
        socket.receive(state({ state: 'paused', achieved_speed: 0 }));
        socket.receive(frame(0.2, [0.3], [0.01]));
        socket.reply('live.start', started);
        await going;
        expect(session.status.phase).toBe('paused');
        expect(session.values.get('Step#out#Value')).toBe(0.3);
    });

    it('follows pause, resume, speed and step, and says when the server cannot keep up', async () => {
        const { socket, session } = await live();
        const pausing = session.pause();
        socket.reply('live.pause', { state: 'paused', speed: 1, model_time: 1.2 });
        await pausing;
        expect(session.status).toMatchObject({ phase: 'paused', modelTime: 1.2 });
        const stepping = session.step(333);
        expect(socket.last('live.step')).toMatchObject({ session_id: 3, steps: 333 });
        socket.reply('live.step', { state: 'paused', speed: 1, model_time: 1.2333 });
        await stepping;
        const faster = session.setSpeed(4);
        socket.reply('live.speed', { state: 'paused', speed: 4, model_time: 1.2333 });
        await faster;
        const resuming = session.resume();
        socket.reply('live.resume', { state: 'running', speed: 4, model_time: 1.2333 });
        await resuming;
        expect(session.status).toMatchObject({ phase: 'running', speed: 4, behind: false });
        // a session just resumed has measured nothing yet: not behind
        socket.receive(state({ speed: 4, achieved_speed: 0, model_time: 1.2333 }));
        expect(session.status.behind).toBe(false);
        socket.receive(state({ speed: 4, achieved_speed: 2.7, model_time: 3 }));
        expect(session.status).toMatchObject({ behind: true, achievedSpeed: 2.7 });
        socket.receive(state({ speed: 4, achieved_speed: 4, model_time: 4 }));
        expect(session.status.behind).toBe(false);
    });

    it('ends when the server stops it, saying why (stop time, idle timeout)', async () => {
        const first = await live();
        first.socket.receive(state({ state: 'stopped', achieved_speed: 0, model_time: 10, reason: 'finished' }));
        expect(first.session.status.phase).toBe('stopped');
        expect(first.session.status.message).toMatch(/stop time, t = 10 s/);
        expect(first.session.active).toBe(false);
        // a set after the end is not sent
        expect(await first.session.set('Step.y_A', 1)).toBe(false);
        expect(first.socket.sent.filter((m) => m.type === 'live.set')).toHaveLength(0);

        const second = await live();
        second.socket.receive(state({ state: 'stopped', achieved_speed: 0, model_time: 4, reason: 'idle_timeout',
            message: "no message from the session's owner for 600000 ms (--live-idle-timeout)" }));
        expect(second.session.status.message).toMatch(/too long.*--live-idle-timeout.*Go live again/);
    });

    it('stopping says so, whether the stopped event or the reply comes first', async () => {
        const replyFirst = await live();
        const stopping = replyFirst.session.stop();
        replyFirst.socket.reply('live.stop', { state: 'stopped', speed: 1, model_time: 2.5 });
        await stopping;
        replyFirst.socket.receive(state({ state: 'stopped', achieved_speed: 0, model_time: 2.5, reason: 'requested' }));
        expect(replyFirst.session.status).toMatchObject({ phase: 'stopped', message: 'Stopped at t = 2.5 s.' });

        const eventFirst = await live();
        const stopping2 = eventFirst.session.stop();
        eventFirst.socket.receive(state({ state: 'stopped', achieved_speed: 0, model_time: 1.75, reason: 'requested' }));
        eventFirst.socket.reply('live.stop', { state: 'stopped', speed: 1, model_time: 1.75 });
        await stopping2;
        expect(eventFirst.session.status).toMatchObject({ phase: 'stopped', message: 'Stopped at t = 1.75 s.' });
    });

    it('a full recording is a notice: the session goes on', async () => {
        const { socket, session } = await live();
        socket.receive(state({ reason: 'record_limit', message: 'at most 100000 samples (--max-log-samples)' }));
        expect(session.status.phase).toBe('running');
        expect(session.status.notice).toMatch(/recording is full.*--max-log-samples/);
    });

    it('a value that needs a new start is refused in words that name it; the session goes on', async () => {
        const { socket, session } = await live();
        const setting = session.set('Mass.m', 200);
        expect(socket.last('live.set')).toMatchObject({ session_id: 3, name: 'Mass.m', value: 200 });
        socket.refuse('live.set', 'restart_required', 'Mass.m only changes with a new start');
        expect(await setting).toBe(false);
        expect(session.status.phase).toBe('running');
        expect(session.status.message).toMatch(/^Set Mass\.m: Mass\.m only changes with a new start\. .*stop, change the parameter, and go live again/);
    });

    it('a refused start says that too many live sessions run, and what to do', async () => {
        const { socket, session } = await setup();
        const going = session.start(12, [], 1);
        socket.refuse('live.start', 'rate_limited', 'at most 2 live sessions per user (--max-live-sessions-per-user)');
        expect(await going).toBe(false);
        expect(session.status.phase).toBe('stopped');
        expect(session.status.message).toMatch(/Go live: .*as many live sessions.*--max-live-sessions-per-user.*Stop one/);
    });

    it('records and hands back the stored run', async () => {
        const { socket, session } = await live();
        const recording = session.record();
        socket.reply('live.record', { job_id: 88, samples: 412, changes: [], full: false });
        expect(await recording).toMatchObject({ job_id: 88, samples: 412 });
    });

    it('a lost socket ends the session in the UI (the server ended it with the socket)', async () => {
        const { socket, session, client } = await live(true);
        socket.close();
        expect(client.status).toBe('reconnecting');
        expect(session.status.phase).toBe('stopped');
        expect(session.status.message).toMatch(/connection to the server was lost/);
    });

    it('live events go to live listeners only, not to the job listeners', async () => {
        const { socket, client } = await live();
        const jobEvents: unknown[] = [];
        client.onEvent((e) => jobEvents.push(e));
        socket.receive(frame(0.1, [0], [0]));
        socket.receive(state({}));
        expect(jobEvents).toEqual([]);
    });

    it('watches a session read-only: live.subscribe, then its frames, and a stop says the teacher stopped sharing', async () => {
        const { socket, session } = await setup();
        const watching = session.watch(3);
        expect(socket.last('live.subscribe')).toMatchObject({ session_id: 3, frames: 'json' });
        socket.reply('live.subscribe', { state: 'running', speed: 1, model_time: 1.2 });
        expect(await watching).toBe(true);
        expect(session.status.phase).toBe('running');
        expect(session.liveValues).toEqual([]);
        const heard: number[] = [];
        session.onFrame((_, f) => heard.push(f.model_time));
        socket.receive(frame(1.3, [0.2], [0.001]));
        expect(heard).toEqual([1.3]);
        expect(session.status.modelTime).toBe(1.3);
        // nothing is sent for a watcher's set
        expect(await session.set('Step.y_A', 1)).toBe(false);
        expect(socket.sent.some((m) => m.type === 'live.set')).toBe(false);
        socket.receive(state({ state: 'stopped', achieved_speed: 0, model_time: 1.4, reason: 'unshared' }));
        expect(session.status.phase).toBe('stopped');
        expect(session.status.message).toContain('stopped sharing');
    });

    it('a session that is not there to watch is refused in words', async () => {
        const { socket, session } = await setup();
        const watching = session.watch(9);
        socket.refuse('live.subscribe', 'not_found', 'no such live session');
        expect(await watching).toBe(false);
        expect(session.status.phase).toBe('stopped');
        expect(session.status.message).toContain('ended');
    });
});
