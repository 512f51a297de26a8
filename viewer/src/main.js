// The page `yamsc view` writes: the run embedded as JSON in <script id="yamsc-run">
// (docs/viewer.md: the layout), drawn with three.js, its channels plotted under it.
// window.yamscView exposes the clock so that a test (tests/view) can watch it move.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { decodeRun } from './data.js';
import { createPlots } from './plots.js';
import { frameAt } from './clock.js';

const KIND_FRAME_AXIS = 0;
const KIND_BOX = 4;

// Distinct, readable on the light background; a part's colour is its index modulo.
const PALETTE = [0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2,
                 0x17becf, 0xbcbd22, 0x7f7f7f];

function partColor(part) { return new THREE.Color(PALETTE[part % PALETTE.length]); }

// The cells of the scene grouped per part and cell type, as index lists into the points.
function groupCells(run) {
    const groups = new Map();
    const group = (part, kind) => {
        const key = part * 8 + kind;
        if (!groups.has(key)) groups.set(key, { part, kind, segments: [], triangles: [], verts: [] });
        return groups.get(key);
    };
    const { offsets, connectivity, type, part, kind } = run.cells;
    for (let c = 0; c < type.length; ++c) {
        const begin = c === 0 ? 0 : offsets[c - 1];
        const ids = connectivity.subarray(begin, offsets[c]);
        const g = group(part[c], kind[c]);
        if (type[c] === 0) for (const id of ids) g.verts.push(id);
        else if (type[c] === 1)
            for (let i = 0; i + 1 < ids.length; ++i) g.segments.push(ids[i], ids[i + 1]);
        else // a polygon: a fan (the scene's polygons are convex: quads and triangles)
            for (let i = 1; i + 1 < ids.length; ++i) g.triangles.push(ids[0], ids[i], ids[i + 1]);
    }
    return [...groups.values()];
}

function boundingBox(run) {
    const box = new THREE.Box3();
    const p = run.positions;
    const v = new THREE.Vector3();
    for (let i = 0; i < p.length; i += 3) box.expandByPoint(v.set(p[i], p[i + 1], p[i + 2]));
    return box;
}

function buildScene(run, scene, width, height) {
    const positions = new THREE.BufferAttribute(new Float32Array(run.pointCount * 3), 3);
    positions.setUsage(THREE.DynamicDrawUsage);
    const lines = [];
    const meshes = [];
    const pickable = [];
    for (const g of groupCells(run)) {
        const color = partColor(g.part);
        const name = run.partNames[g.part] ?? `part ${g.part}`;
        if (g.triangles.length) {
            const geometry = new THREE.BufferGeometry();
            geometry.setAttribute('position', positions);
            geometry.setIndex(g.triangles);
            const material = new THREE.MeshStandardMaterial({
                color, side: THREE.DoubleSide, roughness: 0.7, metalness: 0.05,
                // A box stands for a body's inertia: see-through, so that what is inside shows.
                transparent: g.kind === KIND_BOX, opacity: g.kind === KIND_BOX ? 0.35 : 1,
                depthWrite: g.kind !== KIND_BOX });
            const mesh = new THREE.Mesh(geometry, material);
            mesh.userData.part = name;
            meshes.push(mesh);
            pickable.push(mesh);
            scene.add(mesh);
        }
        if (g.segments.length) {
            const geometry = new LineSegmentsGeometry();
            const pairs = new Uint32Array(g.segments);
            geometry.setPositions(new Float32Array(pairs.length * 3));
            const material = new LineMaterial({
                color: g.kind === KIND_FRAME_AXIS ? 0x555555 : color,
                linewidth: g.kind === KIND_FRAME_AXIS ? 1.5 : 4, worldUnits: false });
            material.resolution.set(width, height);
            const line = new LineSegments2(geometry, material);
            line.userData.part = name;
            line.frustumCulled = false;
            lines.push({ line, pairs, material });
            pickable.push(line);
            scene.add(line);
        }
        if (g.verts.length) {
            const geometry = new THREE.BufferGeometry();
            geometry.setAttribute('position', positions);
            geometry.setIndex(g.verts);
            const points = new THREE.Points(geometry, new THREE.PointsMaterial({
                color, size: 7, sizeAttenuation: false }));
            points.userData.part = name;
            points.frustumCulled = false;
            pickable.push(points);
            scene.add(points);
        }
    }
    const show = (frame) => {
        const n = run.pointCount * 3;
        const slice = run.positions.subarray(frame * n, frame * n + n);
        positions.array.set(slice);
        positions.needsUpdate = true;
        for (const mesh of meshes) {
            mesh.geometry.computeVertexNormals();
            mesh.geometry.computeBoundingSphere();
        }
        for (const { line, pairs } of lines) {
            const buffer = line.geometry.attributes.instanceStart.data;
            const a = buffer.array;
            for (let i = 0; i < pairs.length; ++i) {
                const p = pairs[i] * 3;
                a[3 * i] = slice[p];
                a[3 * i + 1] = slice[p + 1];
                a[3 * i + 2] = slice[p + 2];
            }
            buffer.needsUpdate = true;
            line.geometry.computeBoundingSphere();
        }
    };
    const resize = (w, h) => { for (const { material } of lines) material.resolution.set(w, h); };
    return { show, resize, pickable };
}

function main() {
    const errors = [];
    const state = {
        ready: false, time: 0, frame: 0, frames: 0, playing: true, speed: 1, renders: 0, errors,
    };
    window.yamscView = state;
    const run = decodeRun(document.getElementById('yamsc-run').textContent);
    state.frames = run.times.length;
    state.pointCount = run.pointCount;
    const t0 = run.times[0];
    const t1 = run.times[run.times.length - 1];
    state.time = t0;

    const view = document.getElementById('view');
    let renderer;
    try {
        renderer = new THREE.WebGLRenderer({ antialias: true });
    } catch (e) {
        view.textContent = 'This browser cannot draw WebGL: ' + e.message;
        throw e;
    }
    renderer.setPixelRatio(window.devicePixelRatio);
    view.appendChild(renderer.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf4f6f8);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 2.0));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    scene.add(sun);

    const box = boundingBox(run);
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
    const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 100);
    camera.up.set(0, 0, 1); // the scene's inertial frame has z up
    // From upwind (−x), to one side and above: the rotor's face and the tower both show.
    const direction = new THREE.Vector3(-1, -0.75, 0.45).normalize();
    // The whole run's bounding sphere fills the height of the view.
    const distance = radius / Math.tan(THREE.MathUtils.degToRad(40) / 2);
    camera.position.copy(center).addScaledVector(direction, distance);
    sun.position.copy(camera.position).add(new THREE.Vector3(0, 0, radius));
    const controls = new OrbitControls(camera, renderer.domElement);
    controls.target.copy(center);
    controls.update();

    const drawn = buildScene(run, scene, 1, 1);
    const plots = createPlots(document.getElementById('plots'), run, (t) => seek(t));

    const playButton = document.getElementById('play');
    const scrub = document.getElementById('scrub');
    const speed = document.getElementById('speed');
    const clock = document.getElementById('clock');
    const tip = document.getElementById('tip');
    scrub.max = String(state.frames - 1);

    function showFrame(frame) {
        state.frame = frame;
        drawn.show(frame);
        scrub.value = String(frame);
        clock.textContent = `t = ${state.time.toFixed(2)} s / ${t1.toFixed(2)} s`;
        plots.cursor(state.time);
    }
    function seek(t) {
        state.time = Math.min(Math.max(t, t0), t1);
        showFrame(frameAt(run.times, state.time));
    }
    function setPlaying(p) {
        state.playing = p;
        playButton.textContent = p ? 'Pause' : 'Play';
    }
    state.play = () => setPlaying(true);
    state.pause = () => setPlaying(false);
    state.seek = seek;
    playButton.addEventListener('click', () => setPlaying(!state.playing));
    scrub.addEventListener('input', () => {
        setPlaying(false);
        const f = Number(scrub.value);
        state.time = run.times[f];
        showFrame(f);
    });
    speed.addEventListener('change', () => { state.speed = Number(speed.value); });
    window.addEventListener('keydown', (e) => {
        if (e.code === 'Space' && e.target === document.body) {
            setPlaying(!state.playing);
            e.preventDefault();
        }
    });

    const raycaster = new THREE.Raycaster();
    raycaster.params.Points.threshold = radius / 100;
    raycaster.params.Line2 = { threshold: 6 };
    const pointer = new THREE.Vector2();
    renderer.domElement.addEventListener('pointermove', (e) => {
        const r = renderer.domElement.getBoundingClientRect();
        pointer.set(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
        raycaster.setFromCamera(pointer, camera);
        const hit = raycaster.intersectObjects(drawn.pickable, false)[0];
        if (hit) {
            tip.textContent = hit.object.userData.part;
            tip.style.left = `${e.clientX - r.left + 12}px`;
            tip.style.top = `${e.clientY - r.top + 12}px`;
            tip.hidden = false;
        } else {
            tip.hidden = true;
        }
        state.hovered = hit ? hit.object.userData.part : null;
    });
    renderer.domElement.addEventListener('pointerleave', () => { tip.hidden = true; });
    // Where point i of the frame shown is on the screen (client pixels): for tests.
    state.screenPosition = (i) => {
        const n = run.pointCount * 3;
        const p = run.positions.subarray(state.frame * n + 3 * i, state.frame * n + 3 * i + 3);
        const v = new THREE.Vector3(p[0], p[1], p[2]).project(camera);
        const r = renderer.domElement.getBoundingClientRect();
        return { x: r.left + (v.x + 1) / 2 * r.width, y: r.top + (1 - v.y) / 2 * r.height };
    };

    function resize() {
        const w = view.clientWidth;
        const h = view.clientHeight;
        renderer.setSize(w, h, false);
        camera.aspect = w / Math.max(h, 1);
        camera.updateProjectionMatrix();
        drawn.resize(w, h);
        plots.resize();
    }
    window.addEventListener('resize', resize);
    resize();
    showFrame(0);
    // page.html#t=45: opens paused at that time (a link to a moment, a screenshot).
    const start = /(?:^#|&)t=([0-9.eE+-]+)/.exec(window.location.hash);
    if (start && Number.isFinite(Number(start[1]))) {
        setPlaying(false);
        seek(Number(start[1]));
    }

    let last = performance.now();
    renderer.setAnimationLoop((now) => {
        const dt = Math.min((now - last) / 1000, 0.25);
        last = now;
        if (state.playing && state.frames > 1) {
            let t = state.time + dt * state.speed;
            if (t > t1) t = t0 + (t - t1) % Math.max(t1 - t0, 1e-9); // loops
            state.time = t;
            const f = frameAt(run.times, t);
            if (f !== state.frame) showFrame(f);
            else clock.textContent = `t = ${t.toFixed(2)} s / ${t1.toFixed(2)} s`;
            plots.cursor(t);
        }
        controls.update();
        renderer.render(scene, camera);
        state.renders += 1;
    });
    state.ready = true;
}

main();
