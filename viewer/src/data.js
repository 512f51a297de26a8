// The run as the page embeds it (docs/viewer.md): JSON whose arrays are base64 of
// little-endian typed arrays, so that 60 s of a turbine stay a few megabytes.

function bytes(base64) {
    const text = atob(base64);
    const out = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) out[i] = text.charCodeAt(i);
    return out.buffer;
}

const f64 = (s) => new Float64Array(bytes(s));
const f32 = (s) => new Float32Array(bytes(s));
const i32 = (s) => new Int32Array(bytes(s));
const u8 = (s) => new Uint8Array(bytes(s));

export function decodeRun(json) {
    const d = JSON.parse(json);
    if (d.format !== 'yamsc-view 1') throw new Error(`unknown data format '${d.format}'`);
    const run = {
        title: d.title,
        partNames: d.parts,
        pointCount: d.points,
        times: f64(d.times),
        positions: f32(d.positions),
        cells: {
            type: u8(d.cells.type),
            offsets: i32(d.cells.offsets),
            connectivity: i32(d.cells.connectivity),
            part: i32(d.cells.part),
            kind: u8(d.cells.kind),
        },
        channels: {
            times: f64(d.channels.times),
            series: d.channels.series.map((s) => ({ name: s.name, unit: s.unit, values: f32(s.values) })),
        },
    };
    if (run.positions.length !== run.times.length * run.pointCount * 3)
        throw new Error('positions do not match frames x points');
    return run;
}
