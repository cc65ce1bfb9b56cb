// What the viewer's end-to-end tests share: their arguments, checks that print what held, the
// server (`tvf serve` on a small mesh, its printed address), and headless Chromium opened with a
// fresh profile.  The server and the profile never outlive the test, whichever way it ends: a
// failure, a signal (CTest's timeout), or the watchdog, which ends a hung test first.
import { createRequire } from 'node:module';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

// --key value pairs (--node-modules becomes nodeModules); the four paths are required.
export function options(argv, defaults = {}) {
  const o = { chromium: '/usr/bin/chromium', ...defaults };
  for (let i = 2; i < argv.length; i += 2) {
    if (!argv[i].startsWith('--') || i + 1 >= argv.length) throw new Error(`bad argument ${argv[i]}`);
    o[argv[i].slice(2).replace(/-(.)/g, (_, c) => c.toUpperCase())] = argv[i + 1];
  }
  for (const required of ['tvf', 'mesh', 'nodeModules', 'artifacts']) {
    if (!o[required]) throw new Error(`missing --${required.replace(/[A-Z]/g, (c) => '-' + c.toLowerCase())}`);
  }
  return o;
}

export function check(condition, what) {
  if (!condition) throw new Error(`check failed: ${what}`);
  console.log(`ok: ${what}`);
}

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Starts `tvf serve` with a basis of `eigenfields`; `url` resolves with its address once it
// prints "listening on ...".
export function startServer(o, eigenfields) {
  const server = spawn(o.tvf, ['serve', o.mesh, '--port', '0', '-n', String(eigenfields)],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  let stderr = '';
  server.stderr.on('data', (d) => { stderr += d; process.stderr.write(`[tvf] ${d}`); });
  const url = new Promise((resolve, reject) => {
    let stdout = '';
    server.stdout.on('data', (d) => {
      stdout += d;
      const m = stdout.match(/listening on (http:\/\/\S+)/);
      if (m) resolve(m[1]);
    });
    server.on('exit', (code) => reject(new Error(`tvf serve exited (${code}) before listening: ${stderr}`)));
    setTimeout(() => reject(new Error('tvf serve did not print its address within 60 s')), 60000);
  });
  return { server, url };
}

// The server of `o`, then headless Chromium with its first page, whose errors are collected
// in `problems`.  `name` labels the profile and the watchdog's message.
export async function openViewer(o, name, { eigenfields = 10, watchdogSeconds = 100 } = {}) {
  const require = createRequire(path.join(path.resolve(o.nodeModules), '..', 'package.json'));
  const { chromium } = require('playwright-core');
  fs.mkdirSync(o.artifacts, { recursive: true });
  const { server, url } = startServer(o, eigenfields);
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), `tvf-e2e-${name}-`));
  process.on('exit', () => {
    server.kill('SIGTERM');
    fs.rmSync(profile, { recursive: true, force: true });
  });
  for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => process.exit(1));
  setTimeout(() => {
    console.error(`${name} e2e: FAILED: no result within ${watchdogSeconds} s`);
    process.exit(1);
  }, watchdogSeconds * 1000).unref();
  const address = await url;
  console.log(`server at ${address}`);
  const browser = await chromium.launchPersistentContext(profile, {
    executablePath: o.chromium,
    headless: true,
    viewport: { width: 1200, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = browser.pages()[0] || await browser.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  return { address, browser, page, problems };
}

// Runs the test `body` and exits with its verdict.
export function runTest(name, body) {
  body().then(() => {
    console.log(`${name} e2e: passed`);
    process.exit(0);
  }, (e) => {
    console.error(`${name} e2e: FAILED: ${e.stack || e.message}`);
    process.exit(1);
  });
}
