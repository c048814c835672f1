// Browser test of the pages the CLI writes: `detect --html` (explain) and `dock --html` /
// `view --html` (replay), opened from file:// in Debian's chromium driven by playwright-core.
// It checks from each page's state and canvas pixels that the shelf, legs and path are drawn where
// the data (and the simulator's ground truth) say, steps the timeline, loads a second record (no
// stale drawing) and saves screenshots.
//
// usage: node pages_test.mjs SHELFDOCK_BINARY REPO_ROOT SCREENSHOT_DIR
// Exit 0 pass, 1 fail, 77 skip (only when the browser cannot start; the reason is printed).
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [binary, root, shots] = process.argv.slice(2);
if (!binary || !root || !shots) {
  console.error("usage: node pages_test.mjs SHELFDOCK_BINARY REPO_ROOT SCREENSHOT_DIR");
  process.exit(1);
}
let chromium;
try {
  ({ chromium } = await import("playwright-core"));
} catch (err) {
  console.error(`FAIL: playwright-core is not installed (run \`npm ci\` in tests/browser, as scripts/test.sh does): ${err.message}`);
  process.exit(1);
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), "shelfdock-browser-"));
fs.mkdirSync(shots, { recursive: true });
let failures = 0;
function check(cond, what) {
  console.log(`${cond ? "ok  " : "FAIL"} ${what}`);
  if (!cond) ++failures;
}
const near = (a, b, tol) => Math.abs(a - b) <= tol;
const angleDiff = (a, b) => Math.atan2(Math.sin(a - b), Math.cos(a - b));
function run(...args) {
  return execFileSync(binary, args, { cwd: root, encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
}
const readLines = (file) => fs.readFileSync(file, "utf8").split("\n").filter((l) => l.trim()).map((l) => JSON.parse(l));

// --- data: two simulated scans of the paper's scene, and two docking runs -------------------
const scans = path.join(tmp, "scans.jsonl"), truthFile = path.join(tmp, "truth.json");
run("simulate", "--scenario", "config/scenarios/paper_docking.yaml", "--pose", "3.0,2.3,0.1", "--count", "2",
  "--seed", "5", "--out", scans, "--truth", truthFile);
const truth = JSON.parse(fs.readFileSync(truthFile, "utf8"));
const explainPage = path.join(tmp, "explain.html"), emptyPage = path.join(tmp, "explain_no_shelf.html");
run("detect", "--models", "config/models.yaml", "--scan", scans, "--html", explainPage);
// A preset 2 m behind the sensor: the ROI holds nothing, the page must say so.
run("detect", "--models", "config/models.yaml", "--scan", scans, "--preset", "-2,0,0", "--html", emptyPage);
const recordA = path.join(tmp, "run_a.jsonl"), recordB = path.join(tmp, "run_b.jsonl");
const replayPage = path.join(tmp, "replay.html"), viewPage = path.join(tmp, "view.html");
run("dock", "--seed", "3", "--record", recordA, "--html", replayPage);
run("dock", "--seed", "4", "--method", "stop-and-recognise", "--record", recordB);
run("view", recordA, recordB, "--html", viewPage);
const linesA = readLines(recordA), linesB = readLines(recordB);

// --- browser -----------------------------------------------------------------------------------
let browser;
try {
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    // This machine's network is closed: without these flags chromium keeps trying to reach
    // Google's services at every start.
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
      "--disable-component-update", "--disable-sync"],
  });
} catch (err) {
  console.log(`SKIP: the browser cannot start (${(err.message || String(err)).split("\n")[0]}); install Debian's chromium (scripts/install_deps.sh)`);
  process.exit(77);
}

async function open(file) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 850 } });
  const errors = [], requests = [];
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("request", (r) => { if (!r.url().startsWith("file:")) requests.push(r.url()); });
  await page.goto("file://" + file);
  return { page, errors, requests };
}
// The canvas colours in a (2r+1)^2 pixel block around world point (x, y) of the page's view.
async function pixelsAt(page, stateName, x, y, r = 1) {
  return page.evaluate(({ stateName, x, y, r }) => {
    const v = window[stateName].view, [px, py] = v.toPx(x, y);
    const d = v.ctx.getImageData(Math.round(px) - r, Math.round(py) - r, 2 * r + 1, 2 * r + 1).data;
    const out = [];
    for (let k = 0; k < d.length; k += 4) out.push([d[k], d[k + 1], d[k + 2], d[k + 3]]);
    return out;
  }, { stateName, x, y, r });
}
const hasColour = (pixels, rgb, tol = 40) => pixels.some((p) => p[3] > 200 && Math.abs(p[0] - rgb[0]) <= tol && Math.abs(p[1] - rgb[1]) <= tol && Math.abs(p[2] - rgb[2]) <= tol);
const GREEN = [0, 170, 0], ORANGE = [230, 126, 0], BLUE = [0, 102, 204];

try {
  // --- explain page: a shelf found ---------------------------------------------------------
  {
    const { page, errors, requests } = await open(explainPage);
    const st = () => page.evaluate(() => ({ scan: window.shelfdockExplain.scan, highlight: window.shelfdockExplain.highlight, drawn: window.shelfdockExplain.drawn }));
    const data = await page.evaluate(() => embeddedData());
    check(data.scans.length === 2, "explain: the page holds both scans");
    const trueShelf = truth.scans[0].shelves.find((s) => s.id === truth.target_shelf);
    let s = await st();
    check(s.drawn.shelves.length === 1, `explain: one shelf drawn (got ${s.drawn.shelves.length})`);
    const d = s.drawn.shelves[0];
    // Tolerance: the README's detection figures (p95 centre error 6.7 mm); 2 cm leaves room.
    check(near(d.x, trueShelf.x, 0.02) && near(d.y, trueShelf.y, 0.02), `explain: shelf drawn at (${d.x.toFixed(3)}, ${d.y.toFixed(3)}), truth (${trueShelf.x.toFixed(3)}, ${trueShelf.y.toFixed(3)})`);
    check(Math.abs(Math.sin(angleDiff(d.yaw, trueShelf.yaw))) < 0.02, "explain: shelf heading matches the truth (modulo pi)");
    check(d.model === trueShelf.model, `explain: model ${d.model}`);
    const dataShelf = data.scans[0].detections[0];
    check(d.x === dataShelf.x && d.y === dataShelf.y, "explain: drawn where the page data says");
    let legsGreen = 0;
    for (const l of dataShelf.legs) if (hasColour(await pixelsAt(page, "shelfdockExplain", l[0], l[1]), GREEN)) ++legsGreen;
    check(legsGreen === dataShelf.legs.length, `explain: canvas shows the returned legs at their fitted centres (${legsGreen}/${dataShelf.legs.length})`);
    check(s.drawn.candidates.length === data.scans[0].stats.leg_candidates, `explain: ${s.drawn.candidates.length} leg candidates drawn, stats say ${data.scans[0].stats.leg_candidates}`);
    check(data.scans[0].candidates.length >= data.scans[0].stats.leg_candidates, `explain: the page lists ${data.scans[0].candidates.length} candidates the search saw, stats say ${data.scans[0].stats.leg_candidates} from the scan`);
    check(s.drawn.completed.length === data.scans[0].candidates.filter((c) => c.completed).length, `explain: ${s.drawn.completed.length} legs the completion cut drawn`);
    check(s.drawn.points === data.scans[0].points.length && s.drawn.points > 100, `explain: ${s.drawn.points} points drawn`);
    const answer = await page.textContent("#answer");
    check(answer.startsWith("1 shelf found: t1-rect-1075x883"), `explain: answer "${answer.slice(0, 60)}..."`);
    const rows = await page.locator("#hypotheses tbody tr").count();
    check(rows === data.scans[0].hypotheses.length && rows > 0, `explain: ${rows} hypotheses listed`);
    await page.screenshot({ path: path.join(shots, "explain.png") });
    await page.locator("#hypotheses tbody tr").first().click();
    s = await st();
    check(s.highlight === 0 && s.drawn.hypotheses.length <= 1, "explain: clicking a hypothesis shows it alone");
    await page.click("#next");
    s = await st();
    check(s.scan === 1 && s.highlight === -1, "explain: next shows scan 2");
    check(errors.length === 0, `explain: no script errors ${errors.join("; ")}`);
    check(requests.length === 0, `explain: no network requests ${requests.join(" ")}`);
    await page.close();
  }
  // --- explain page: no shelf, and why ------------------------------------------------------
  {
    const { page, errors } = await open(emptyPage);
    const s = await page.evaluate(() => window.shelfdockExplain.drawn);
    check(s.shelves.length === 0, "explain (wrong preset): no shelf drawn");
    check(s.roi && near(s.roi.x, -2, 1e-9) && s.roi.r > 0.5, "explain (wrong preset): ROI drawn around the preset");
    const answer = await page.textContent("#answer");
    check(answer.startsWith("no shelf:") && /ROI|leg-sized/.test(answer), `explain (wrong preset): answer "${answer}"`);
    await page.screenshot({ path: path.join(shots, "explain_no_shelf.png") });
    check(errors.length === 0, `explain (wrong preset): no script errors ${errors.join("; ")}`);
    await page.close();
  }
  // --- replay page ---------------------------------------------------------------------------
  // What the record says at step i: the plan in force and the scan shown.
  const stepsOf = (lines) => lines.filter((l) => l.type === "step");
  const planAt = (steps, i) => { for (let k = i; k >= 0; --k) if (steps[k].path) return steps[k].path; return null; };
  const headerOf = (lines) => lines.find((l) => l.type === "header");
  {
    const { page, errors, requests } = await open(replayPage);
    const st = () => page.evaluate(() => ({ step: window.shelfdockReplay.step, drawn: window.shelfdockReplay.drawn, n: window.shelfdockReplay.run.steps.length }));
    const stepsA = stepsOf(linesA), header = headerOf(linesA);
    const target = header.shelves.find((s) => s.id === header.target_shelf);
    // The first step with a scan and a fused estimate while the robot, still more than 1 m away,
    // drives nearly straight (the record places a scan with the pose at its end: while turning,
    // far returns land off their objects by the turn during the scan).
    const i = stepsA.findIndex((s, k) => k >= 5 && s.scan && s.shelf &&
      Math.abs(angleDiff(s.true.yaw, stepsA[k - 5].true.yaw)) < 0.005 &&
      Math.hypot(s.true.x - s.shelf.x, s.true.y - s.shelf.y) > 1.0);
    check(i > 0, `replay: a step with a scan and a fused estimate 1 m away exists (${i})`);
    await page.evaluate((i) => { const sl = document.getElementById("time"); sl.value = i; sl.dispatchEvent(new Event("input")); }, i);
    let s = await st();
    check(s.step === i, `replay: slider moved to step ${i}`);
    check(s.drawn.fused && s.drawn.fused.x === stepsA[i].shelf.x, "replay: fused shelf drawn where the record says");
    // The fused estimate against the simulator's true shelf (docking's own tolerance is far
    // tighter at the end; 5 cm here, mid-approach).
    check(near(s.drawn.fused.x, target.x, 0.05) && near(s.drawn.fused.y, target.y, 0.05), "replay: fused shelf within 5 cm of the true shelf");
    check(hasColour(await pixelsAt(page, "shelfdockReplay", stepsA[i].shelf.x, stepsA[i].shelf.y), ORANGE), "replay: canvas shows the fused shelf at its centre");
    check(JSON.stringify(s.drawn.path) === JSON.stringify(planAt(stepsA, i)), "replay: the plan in force is drawn");
    const plan = planAt(stepsA, i), q = plan[Math.floor(plan.length * 0.8)];
    check(hasColour(await pixelsAt(page, "shelfdockReplay", q[0], q[1], 2), BLUE), "replay: canvas shows the plan ahead of the robot");
    if (stepsA[i].detection) {
      check(near(s.drawn.fitted.length, target.length, 1e-9) && near(s.drawn.fitted.width, target.width, 1e-9), "replay: fitted shelf drawn with the target's size");
      check(s.drawn.keptLegs.length > 0, `replay: ${s.drawn.keptLegs.length} scan returns on the kept legs`);
    }
    check(s.drawn.scan > 0, `replay: scan drawn (${s.drawn.scan} points)`);
    await page.screenshot({ path: path.join(shots, "replay_approach.png") });
    // Step forward and back with the buttons and the keyboard.
    await page.click("#fwd"); s = await st(); check(s.step === i + 1, "replay: step forward");
    await page.click("#back"); await page.click("#back"); s = await st(); check(s.step === i - 1, "replay: step back twice");
    await page.keyboard.press("ArrowRight"); s = await st(); check(s.step === i, "replay: right arrow steps");
    // Play at 2x for a moment: the timeline moves on by itself, then pause stops it.
    await page.selectOption("#speed", "2");
    await page.click("#play");
    await page.waitForFunction((i) => window.shelfdockReplay.step > i + 20, i, { timeout: 10000 });
    await page.click("#play");
    const paused = (await st()).step;
    await page.waitForTimeout(300);
    check((await st()).step === paused, "replay: play advances, pause stops");
    // The end: the robot under the shelf, the outcome shown.
    await page.evaluate(() => { const sl = document.getElementById("time"); sl.value = sl.max; sl.dispatchEvent(new Event("input")); });
    s = await st();
    check(s.step === s.n - 1 && s.n === stepsA.length, "replay: last step shown");
    const summary = await page.textContent("#summary");
    check(summary.includes("success"), "replay: outcome shown");
    await page.screenshot({ path: path.join(shots, "replay_end.png") });
    // A second record from the file box: nothing of the first may remain.
    await page.setInputFiles("#file", recordB);
    await page.waitForFunction(() => window.shelfdockReplay.run.name === "run_b.jsonl");
    const stepsB = stepsOf(linesB);
    s = await st();
    check(s.step === 0 && s.n === stepsB.length, "replay: second record loaded at its start");
    check(JSON.stringify(s.drawn.path) === JSON.stringify(planAt(stepsB, 0)), "replay: second record's step 0 draws its own plan (or none), not the first record's");
    check(s.drawn.fitted === null && s.drawn.fused === null, "replay: no shelf estimate left over from the first record");
    const last = stepsB.length - 1;
    await page.evaluate(() => { const sl = document.getElementById("time"); sl.value = sl.max; sl.dispatchEvent(new Event("input")); });
    s = await st();
    check(s.drawn.plans === stepsB.filter((x) => x.path).length, `replay: second record's ${s.drawn.plans} plans drawn`);
    check(JSON.stringify(s.drawn.path) === JSON.stringify(planAt(stepsB, last)), "replay: second record's last plan drawn");
    await page.screenshot({ path: path.join(shots, "replay_second_record.png") });
    check(errors.length === 0, `replay: no script errors ${errors.join("; ")}`);
    check(requests.length === 0, `replay: no network requests ${requests.join(" ")}`);
    await page.close();
  }
  // --- view page with two records: switching between them --------------------------------------
  {
    const { page, errors } = await open(viewPage);
    const names = await page.locator("#record option").allTextContents();
    check(names.length === 2, `view: two records in the page (${names.join(", ")})`);
    await page.selectOption("#record", "1");
    const s = await page.evaluate(() => ({ name: window.shelfdockReplay.run.name, n: window.shelfdockReplay.run.steps.length, drawn: window.shelfdockReplay.drawn }));
    check(s.name === recordB && s.n === stepsOf(linesB).length, "view: the second record is shown after switching");
    check(JSON.stringify(s.drawn.path) === JSON.stringify(planAt(stepsOf(linesB), 0)), "view: its own plan, not the first record's");
    await page.screenshot({ path: path.join(shots, "view_two_records.png") });
    check(errors.length === 0, `view: no script errors ${errors.join("; ")}`);
    await page.close();
  }
} finally {
  await browser.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
console.log(`screenshots in ${shots}`);
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);
