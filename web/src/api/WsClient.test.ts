import { describe, expect, it } from 'vitest';
import { WsClient, socketUrl } from './WsClient';
import { ApiError } from './ApiError';
import type { ServerEvent } from '../protocol/types';
import { FakeSocket } from '../testing/FakeSocket';

const hello = { type: 'hello', protocol: 'tlmhub.v1', user: { id: 1, username: 'alice', role: 'user' } };

async function connected() {
    const socket = new FakeSocket();
    const client = new WsClient(() => socket, { enabled: false });
    const ready = client.connect();
    socket.receive(hello);
    await ready;
    return { socket, client };
}

describe('WsClient', () => {
    it('resolves connect with the hello message', async () => {
        const { client } = await connected();
        expect(client.hello?.user.username).toBe('alice');
        expect(client.connected).toBe(true);
    });

    it('sends numbered requests and resolves each with its own reply, in any order', async () => {
        const { socket, client } = await connected();
        const a = client.request('ping');
        const b = client.request('component.move', { name: 'X', pose: { x: 1, y: 2, angle: 0, flipped: false } });
        expect(socket.sent.map((m) => m.type)).toEqual(['ping', 'component.move']);
        expect(socket.sent[1]).toMatchObject({ name: 'X' });
        const [idA, idB] = socket.sent.map((m) => m.id);
        expect(idA).not.toBe(idB);
        socket.receive({ id: idB, type: 'reply', ok: true, data: { which: 'b' } });
        socket.receive({ id: idA, type: 'reply', ok: true, data: { which: 'a' } });
        expect(await a).toEqual({ which: 'a' });
        expect(await b).toEqual({ which: 'b' });
    });

    it('rejects with the error code and message of an error reply', async () => {
        const { socket, client } = await connected();
        const p = client.request('connect', { from: { component: 'A', port: 'out' }, to: { component: 'B', port: 'out' } });
        socket.receive({ id: socket.sent[0].id, type: 'error', error: { code: 'illegal_connection', message: 'A.out and B.out are both write ports' } });
        const err = await p.catch((e: unknown) => e);
        expect(err).toBeInstanceOf(ApiError);
        expect((err as ApiError).code).toBe('illegal_connection');
        expect((err as ApiError).message).toBe('A.out and B.out are both write ports');
    });

    it('sends model.open again a second later while the server is busy, and gives up after five tries', async () => {
        const socket = new FakeSocket();
        const timers: { fn: () => void; ms: number }[] = [];
        const client = new WsClient(() => socket, { enabled: false, setTimer: (fn, ms) => timers.push({ fn, ms }) });
        const ready = client.connect();
        socket.receive(hello);
        await ready;
        const busy = (id: unknown) => ({ id, type: 'error', error: { code: 'busy', message: 'at most 2 large replies' } });
        const settle = () => new Promise((resolve) => setTimeout(resolve, 0));

        const opened = client.request('model.open', { model_id: 3 });
        socket.receive(busy(socket.sent[0].id));
        await settle();
        expect(timers.map((t) => t.ms)).toEqual([1000]);
        expect(socket.sent).toHaveLength(1);   // nothing sent before the second has passed
        timers[0].fn();
        await settle();
        expect(socket.sent.map((m) => m.type)).toEqual(['model.open', 'model.open']);
        expect(socket.sent[1]).toMatchObject({ model_id: 3 });
        socket.receive({ id: socket.sent[1].id, type: 'reply', ok: true, data: { model_id: 3 } });
        expect(await opened).toEqual({ model_id: 3 });

        const refused = client.request('model.get').catch((e: unknown) => e);
        for (let attempt = 0; attempt < 6; ++attempt) {
            socket.receive(busy(socket.sent[socket.sent.length - 1].id));
            await settle();
            if (attempt < 5) timers[timers.length - 1].fn();
            await settle();
        }
        const err = await refused;
        expect((err as ApiError).code).toBe('busy');
        expect(socket.sent.filter((m) => m.type === 'model.get')).toHaveLength(6);
    });

    it('does not send an edit again when the server answers busy', async () => {
        const { socket, client } = await connected();
        const p = client.request('ping').catch((e: unknown) => e);
        socket.receive({ id: socket.sent[0].id, type: 'error', error: { code: 'busy', message: 'too many messages' } });
        expect(((await p) as ApiError).code).toBe('busy');
        expect(socket.sent).toHaveLength(1);
    });

    it('the field "type" of a request cannot overwrite the message type', async () => {
        const { socket, client } = await connected();
        // @ts-expect-error: the typed fields have no "type"; untyped callers could still send one
        void client.request('simulate.start', { type: 'oops', stop: 2 });
        expect(socket.sent[0]).toMatchObject({ type: 'simulate.start', stop: 2 });
    });

    it('passes events to listeners and ignores replies nobody waits for', async () => {
        const { socket, client } = await connected();
        const seen: ServerEvent[] = [];
        const off = client.onEvent((e) => seen.push(e));
        socket.receive({ type: 'event.progress', job_id: 3, progress: 0.5 });
        socket.receive({ id: 999, type: 'reply', ok: true, data: {} });
        socket.receive('not json');
        off();
        socket.receive({ type: 'event.progress', job_id: 3, progress: 0.9 });
        expect(seen).toEqual([{ type: 'event.progress', job_id: 3, progress: 0.5 }]);
    });

    it('fails pending requests when the socket closes (reconnecting off)', async () => {
        const { socket, client } = await connected();
        let closed = false;
        client.onClose(() => { closed = true; });
        const p = client.request('ping');
        socket.onclose?.({});
        await expect(p).rejects.toMatchObject({ code: 'connection_lost' });
        expect(closed).toBe(true);
        await expect(client.request('ping')).rejects.toMatchObject({ code: 'not_connected' });
    });

    it('rejects connect when the socket closes before hello', async () => {
        const socket = new FakeSocket();
        const client = new WsClient(() => socket);
        const ready = client.connect();
        socket.onclose?.({});
        await expect(ready).rejects.toBeInstanceOf(ApiError);
    });

    it('builds the socket URL with the token', () => {
        expect(socketUrl('a b', { protocol: 'http:', host: 'h:1' })).toBe('ws://h:1/api/v1/ws?token=a%20b');
        expect(socketUrl('t', { protocol: 'https:', host: 'h' })).toBe('wss://h/api/v1/ws?token=t');
    });
});
