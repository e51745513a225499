import { describe, expect, it } from 'vitest';
import { decodeBinaryFrame } from './binaryFrame';
import { WsClient, type SocketLike } from './WsClient';
import type { ServerEvent } from '../protocol/types';

// Builds a binary frame the way protocol/README.md describes it.
function encode(header: object, columns: number[][], pad = 0): ArrayBuffer {
    const text = new TextEncoder().encode(JSON.stringify(header));
    const dataOffset = Math.ceil((4 + text.length) / 8) * 8;
    const count = columns.reduce((n, c) => n + c.length, 0);
    const buffer = new ArrayBuffer(dataOffset + count * 8 + pad);
    const view = new DataView(buffer);
    view.setUint32(0, text.length, true);
    new Uint8Array(buffer, 4, text.length).set(text);
    let at = dataOffset;
    for (const column of columns) for (const x of column) { view.setFloat64(at, x, true); at += 8; }
    return buffer;
}

const header = {
    type: 'event.frame', job_id: 41, seq: 3, dropped: 2, time_samples: 3,
    variables: [{ name: 'Step#out#Value', samples: 3 }, { name: 'Gain#out#Value', samples: 2 }],
};

describe('decodeBinaryFrame', () => {
    it('gives the same event a JSON frame gives, every value exact', () => {
        const awkward = [-0, 5e-324, 1.7976931348623157e308];
        const frame = decodeBinaryFrame(encode(header, [[0, 0.005, 0.01], awkward, [NaN, 0.1]]));
        expect(frame).toEqual({
            type: 'event.frame', job_id: 41, seq: 3, dropped: 2, time: [0, 0.005, 0.01],
            variables: { 'Step#out#Value': awkward, 'Gain#out#Value': [NaN, 0.1] },
        });
        expect(Object.is(frame!.variables['Step#out#Value'][0], -0)).toBe(true);
    });

    it('refuses a message that does not add up', () => {
        const good = encode(header, [[0, 1, 2], [3, 4, 5], [6, 7]]);
        expect(decodeBinaryFrame(good)).not.toBeNull();
        expect(decodeBinaryFrame(good.slice(0, good.byteLength - 8))).toBeNull();   // samples missing
        expect(decodeBinaryFrame(encode(header, [[0, 1, 2], [3, 4, 5], [6, 7]], 8))).toBeNull();   // extra bytes
        expect(decodeBinaryFrame(new ArrayBuffer(2))).toBeNull();
        const lying = good.slice(0);
        new DataView(lying).setUint32(0, 1 << 30, true);
        expect(decodeBinaryFrame(lying)).toBeNull();   // header past the end
        expect(decodeBinaryFrame(encode({ ...header, time_samples: -1 }, []))).toBeNull();
    });
});

describe('WsClient with binary frames', () => {
    it('hands a binary message to event listeners as the event.frame it stands for', async () => {
        let socket!: SocketLike;
        const client = new WsClient(() => {
            socket = { onopen: null, onmessage: null, onclose: null, onerror: null, send: () => {}, close: () => {} };
            return socket;
        });
        const ready = client.connect();
        socket.onmessage!({ data: JSON.stringify({ type: 'hello', protocol: 'tlmhub.v1', user: { id: 1, username: 'a', role: 'user' } }) });
        await ready;
        const events: ServerEvent[] = [];
        client.onEvent((e) => events.push(e));
        socket.onmessage!({ data: encode(header, [[0, 1, 2], [3, 4, 5], [6, 7]]) });
        expect(events).toEqual([{
            type: 'event.frame', job_id: 41, seq: 3, dropped: 2, time: [0, 1, 2],
            variables: { 'Step#out#Value': [3, 4, 5], 'Gain#out#Value': [6, 7] },
        }]);
    });
});
