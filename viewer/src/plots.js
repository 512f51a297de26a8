// The channels under the scene: one panel per channel on a 2-D canvas, drawn
// once into an offscreen canvas; each frame only copies it and draws the cursor.
// A click or drag on the panels seeks to that time.

const MARGIN_LEFT = 70;
const MARGIN_RIGHT = 12;
const PANEL_HEIGHT = 84;
const AXIS_HEIGHT = 14; // the strip under the panels with the first and last time

function range(values) {
    let lo = Infinity;
    let hi = -Infinity;
    for (const v of values) { if (v < lo) lo = v; if (v > hi) hi = v; }
    if (!(hi > lo)) { const m = Number.isFinite(lo) ? lo : 0; lo = m - 1; hi = m + 1; }
    const pad = (hi - lo) * 0.06;
    return [lo - pad, hi + pad];
}

const label = (v) => (Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-2 && v !== 0) ? v.toExponential(2) : v.toPrecision(4));

export function createPlots(container, run, onSeek) {
    const series = run.channels.series;
    const times = run.channels.times;
    const canvas = document.createElement('canvas');
    container.appendChild(canvas);
    const background = document.createElement('canvas');
    const t0 = run.times[0];
    const t1 = run.times[run.times.length - 1];
    let width = 1;
    let cursorTime = t0;
    const height = series.length ? PANEL_HEIGHT * series.length + AXIS_HEIGHT : 0;
    container.style.height = `${height}px`;
    container.hidden = series.length === 0;
    const x = (t) => MARGIN_LEFT + ((t - t0) / Math.max(t1 - t0, 1e-12)) * (width - MARGIN_LEFT - MARGIN_RIGHT);

    function drawBackground() {
        const ratio = window.devicePixelRatio || 1;
        for (const c of [canvas, background]) {
            c.width = Math.round(width * ratio);
            c.height = Math.round(height * ratio);
        }
        canvas.style.width = `${width}px`;
        canvas.style.height = `${height}px`;
        const g = background.getContext('2d');
        g.setTransform(ratio, 0, 0, ratio, 0, 0);
        g.fillStyle = '#ffffff';
        g.fillRect(0, 0, width, height);
        g.font = '12px sans-serif';
        series.forEach((s, k) => {
            const top = k * PANEL_HEIGHT + 6;
            const h = PANEL_HEIGHT - 12;
            const [lo, hi] = range(s.values);
            const y = (v) => top + h - ((v - lo) / (hi - lo)) * h;
            g.strokeStyle = '#d0d4da';
            g.strokeRect(MARGIN_LEFT, top, width - MARGIN_LEFT - MARGIN_RIGHT, h);
            g.fillStyle = '#333';
            g.fillText(s.name, 6, top + 14);
            g.fillStyle = '#777';
            if (s.unit) g.fillText(`[${s.unit}]`, 6, top + 30);
            g.fillText(label(hi), 6, top + h - 16);
            g.fillText(label(lo), 6, top + h - 2);
            g.strokeStyle = '#1f77b4';
            g.lineWidth = 1.2;
            g.beginPath();
            for (let i = 0; i < s.values.length; ++i) {
                const px = x(times[i]);
                const py = y(s.values[i]);
                if (i === 0) g.moveTo(px, py); else g.lineTo(px, py);
            }
            g.stroke();
        });
        if (series.length) {
            g.fillStyle = '#777';
            g.fillText(`${t0.toFixed(1)} s`, MARGIN_LEFT, height - 2);
            const end = `${t1.toFixed(1)} s`;
            g.fillText(end, width - MARGIN_RIGHT - g.measureText(end).width, height - 2);
        }
    }

    function cursor(t) {
        cursorTime = t;
        if (!series.length) return;
        const ratio = window.devicePixelRatio || 1;
        const g = canvas.getContext('2d');
        g.setTransform(1, 0, 0, 1, 0, 0);
        g.drawImage(background, 0, 0);
        g.setTransform(ratio, 0, 0, ratio, 0, 0);
        g.strokeStyle = '#d62728';
        g.lineWidth = 1.5;
        g.beginPath();
        g.moveTo(x(t), 0);
        g.lineTo(x(t), height);
        g.stroke();
    }

    function resize() {
        width = Math.max(container.clientWidth, MARGIN_LEFT + MARGIN_RIGHT + 10);
        drawBackground();
        cursor(cursorTime);
    }

    let dragging = false;
    const seekAt = (e) => {
        const r = canvas.getBoundingClientRect();
        const f = (e.clientX - r.left - MARGIN_LEFT) / Math.max(width - MARGIN_LEFT - MARGIN_RIGHT, 1);
        onSeek(t0 + Math.min(Math.max(f, 0), 1) * (t1 - t0));
    };
    canvas.addEventListener('pointerdown', (e) => { dragging = true; seekAt(e); });
    window.addEventListener('pointerup', () => { dragging = false; });
    canvas.addEventListener('pointermove', (e) => { if (dragging) seekAt(e); });
    return { cursor, resize };
}
