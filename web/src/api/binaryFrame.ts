// event.frame as a binary WebSocket message (protocol/README.md, "Binary frames"): a
// little-endian uint32 header length, the JSON header (BinaryFrameHeader), zero bytes up to
// an offset that is a multiple of 8, then float64 little-endian samples: the time vector, then
// each variable's column in the header's order. Decoded into the same FrameEvent a JSON text
// frame gives, so the rest of the app does not know which one came.
import type { BinaryFrameHeader, FrameEvent } from '../protocol/generated';

const littleEndianHost = new Uint8Array(new Float64Array([1]).buffer)[7] === 0x3f;

/** The frame in `data`, or null when it is not a well-formed binary frame. */
export function decodeBinaryFrame(data: ArrayBuffer): FrameEvent | null {
    if (data.byteLength < 4) return null;
    const headerBytes = new DataView(data).getUint32(0, true);
    if (4 + headerBytes > data.byteLength) return null;
    let header: BinaryFrameHeader;
    try {
        header = JSON.parse(new TextDecoder().decode(new Uint8Array(data, 4, headerBytes))) as BinaryFrameHeader;
    } catch {
        return null;
    }
    if (header?.type !== 'event.frame' || !Array.isArray(header.variables)) return null;
    let offset = Math.ceil((4 + headerBytes) / 8) * 8;
    const take = (count: number): number[] | null => {
        if (!Number.isInteger(count) || count < 0 || offset + count * 8 > data.byteLength) return null;
        const values = littleEndianHost
            ? Array.from(new Float64Array(data, offset, count))
            : Array.from({ length: count }, (_, i) => new DataView(data).getFloat64(offset + i * 8, true));
        offset += count * 8;
        return values;
    };
    const time = take(header.time_samples);
    if (!time) return null;
    const variables: Record<string, number[]> = {};
    for (const v of header.variables) {
        const values = take(v.samples);
        if (!values) return null;
        variables[v.name] = values;
    }
    if (offset !== data.byteLength) return null;
    return { type: 'event.frame', job_id: header.job_id, seq: header.seq, time, variables, dropped: header.dropped };
}
