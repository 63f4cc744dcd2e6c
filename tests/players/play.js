// Plays a Lottie file in lottie-web (this folder's pinned copy) in headless
// Chromium, driven by puppeteer-core.
//   node play.js grid ANIM.json OUT.png CELL COLS FRAME...
//     one instance per cell (CELL x CELL pixels, COLS a row), each seeked
//     with goToAndStop(FRAME, true), screenshot to OUT.png
//   node play.js time ANIM.json [REPEAT]
//     one instance at the animation's size; every frame in turn (REPEAT
//     passes) with goToAndStop(frame, true), timed in the page, alone and
//     with the style and layout it causes; prints the load time and the
//     median, 90th percentile and largest milliseconds per frame as JSON
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const { execSync } = require('child_process');
const puppeteer = require('puppeteer-core');

function browserPath() {
    for (const name of ['chromium', 'chromium-browser', 'google-chrome']) {
        try {
            return execSync(`command -v ${name}`, { shell: '/bin/sh' }).toString().trim();
        } catch (e) { /* next */ }
    }
    throw new Error('chromium is not installed (scripts/install-deps.sh installs it)');
}

async function main() {
    const [mode, json, ...rest] = process.argv.slice(2);
    if (!['grid', 'time'].includes(mode) || !json) {
        console.error('usage: node play.js grid ANIM.json OUT.png CELL COLS FRAME... | time ANIM.json [REPEAT]');
        process.exit(2);
    }
    const text = fs.readFileSync(json, 'utf8');
    const data = JSON.parse(text);
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'snaxels-lottie-'));
    fs.writeFileSync(path.join(dir, 'anim.js'), 'window.ANIM = ' + text + ';\n');
    const lottie = require.resolve('lottie-web/build/player/lottie_svg.min.js');
    fs.writeFileSync(path.join(dir, 'page.html'),
        '<!DOCTYPE html><html><head><style>body{margin:0;background:#fff}#grid{display:grid}' +
        '#grid>div{overflow:hidden}</style></head><body><div id="grid"></div>' +
        `<script src="file://${lottie}"></script><script src="anim.js"></script></body></html>`);
    const browser = await puppeteer.launch({
        executablePath: browserPath(),
        headless: true,
        args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--hide-scrollbars'],
        protocolTimeout: 900000,
    });
    try {
        const page = await browser.newPage();
        page.on('pageerror', (e) => { console.error('page error: ' + e.message); process.exitCode = 1; });
        page.on('console', (m) => {
            if (m.type() !== 'error') return;
            console.error(m.text());
            process.exitCode = 1;
        });
        if (mode === 'grid') {
            const [out, cellText, colsText, ...frameTexts] = rest;
            const cell = Number(cellText), cols = Number(colsText), frames = frameTexts.map(Number);
            const rows = Math.ceil(frames.length / cols);
            await page.setViewport({ width: cols * cell, height: rows * cell });
            await page.goto('file://' + path.join(dir, 'page.html'));
            await page.evaluate(async (cell, cols, frames) => {
                const grid = document.getElementById('grid');
                grid.style.gridTemplateColumns = `repeat(${cols}, ${cell}px)`;
                const loads = frames.map((frame) => new Promise((resolve) => {
                    const div = document.createElement('div');
                    div.style.width = div.style.height = cell + 'px';
                    grid.appendChild(div);
                    const anim = lottie.loadAnimation({
                        container: div, renderer: 'svg', loop: false, autoplay: false,
                        animationData: JSON.parse(JSON.stringify(window.ANIM)),
                    });
                    // lottie-web catches what fails while it draws a frame and says so in an event.
                    anim.addEventListener('error', (e) => {
                        console.error('lottie-web: frame ' + frame + ': ' + (e.nativeError ? e.nativeError.message : e.type));
                    });
                    const seek = () => { anim.goToAndStop(frame, true); resolve(); };
                    // Loading may finish within loadAnimation, before a listener could hear it.
                    if (anim.isLoaded) seek();
                    else anim.addEventListener('DOMLoaded', seek);
                }));
                await Promise.all(loads);
                await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
            }, cell, cols, frames);
            await page.screenshot({ path: out });
        } else {
            const repeat = Number(rest[0] || 1);
            await page.setViewport({ width: data.w, height: data.h });
            await page.goto('file://' + path.join(dir, 'page.html'));
            const result = await page.evaluate(async (w, h, frames, repeat) => {
                const div = document.createElement('div');
                div.style.width = w + 'px';
                div.style.height = h + 'px';
                document.getElementById('grid').appendChild(div);
                const t_load = performance.now();
                const anim = lottie.loadAnimation({
                    container: div, renderer: 'svg', loop: false, autoplay: false, animationData: window.ANIM,
                });
                anim.addEventListener('error', (e) => {
                    console.error('lottie-web: ' + (e.nativeError ? e.nativeError.message : e.type));
                });
                if (!anim.isLoaded) await new Promise((r) => anim.addEventListener('DOMLoaded', r));
                const load_ms = performance.now() - t_load;
                const seek = [], layout = [];
                for (let pass = 0; pass < repeat; ++pass)
                    for (let f = 0; f < frames; ++f) {
                        const t0 = performance.now();
                        anim.goToAndStop(f, true);
                        const t1 = performance.now();
                        div.getBoundingClientRect(); // the style and layout the new frame causes
                        const t2 = performance.now();
                        seek.push(t1 - t0);
                        layout.push(t2 - t0);
                        // Let the browser draw as a player would between frames.
                        await new Promise((r) => requestAnimationFrame(r));
                    }
                const stats = (times) => {
                    times.sort((a, b) => a - b);
                    const at = (q) => times[Math.min(times.length - 1, Math.floor(q * times.length))];
                    return { median_ms: at(0.5), p90_ms: at(0.9), max_ms: times[times.length - 1] };
                };
                return { load_ms, calls: seek.length, goToAndStop: stats(seek), with_layout: stats(layout) };
            }, data.w, data.h, Math.round(data.op - data.ip), repeat);
            console.log(JSON.stringify(result));
        }
    } finally {
        await browser.close();
        fs.rmSync(dir, { recursive: true, force: true });
    }
}

main().catch((e) => { console.error(e.message || e); process.exit(1); });
