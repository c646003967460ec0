// Runs the VS Code extension's test (suite.js) in a real VS Code: code-server (VS Code's server and web
// workbench, installed by install.sh) serves a workspace holding copies of tests/editor/*.k, Debian's
// headless Chromium opens the workbench with the extension under development (editors/vscode) and
// suite.js as its tests (the workbench's `payload` query), and the server-side extension host runs them
// against `sphdeck lsp`. The verdict comes back as a file suite.js writes.
//   node driver.mjs SPHDECK SOURCE_DIR      (run_vscode_test.sh checks the install and compiles first)
// Exit 0: passed; 1: a check failed, or something did not start, or the time limit passed.
// SPHDECK_VSCODE_TEST_TIMEOUT_S bounds the whole run (default 150), CHROMIUM names the browser
// (default /usr/bin/chromium), SPHDECK_VSCODE_TEST_KEEP=1 keeps the temporary folder with the logs.
import { spawn } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import os from "node:os";
import path from "node:path";
import http from "node:http";

const [sphdeckArg, sourceArg] = process.argv.slice(2);
if (!sphdeckArg || !sourceArg) {
  console.error("usage: node driver.mjs SPHDECK SOURCE_DIR");
  process.exit(2);
}
const sphdeck = path.resolve(sphdeckArg);
const sourceDir = path.resolve(sourceArg);
const here = path.join(sourceDir, "tests", "editor", "vscode");
const extensionDir = path.join(sourceDir, "editors", "vscode");
const codeServer = path.join(here, "node_modules", "code-server", "out", "node", "entry.js");
const chromium = process.env.CHROMIUM || "/usr/bin/chromium";
const timeoutS = Number(process.env.SPHDECK_VSCODE_TEST_TIMEOUT_S || 150);
const started = Date.now();

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), "sphdeck-vscode-test-"));
const workspace = path.join(tmp, "workspace");
const userData = path.join(tmp, "user-data");
const resultFile = path.join(tmp, "result.json");
const children = [];

function say(text) {
  console.log(`vscode-test: ${text}`);
}

function tail(file, lines, filter = () => true) {
  if (!fs.existsSync(file)) return "";
  return fs.readFileSync(file, "utf8").split("\n").filter(filter).slice(-lines).join("\n");
}

// The logs that tell why: the server's output channel (its stderr, the client's errors), the extension
// host's errors and the extension's activation, code-server's log, the browser console's errors.
function printLogs() {
  const logs = [];
  const walk = (dir) => {
    for (const entry of fs.existsSync(dir) ? fs.readdirSync(dir, { withFileTypes: true }) : []) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (/sphdeck\.log$|^remoteexthost\.log$/.test(entry.name)) logs.push(full);
    }
  };
  walk(path.join(userData, "logs"));
  const telling = (line) => /sphdeck|error|warn/i.test(line);
  for (const file of logs) {
    const all = file.endsWith("sphdeck.log");
    console.error(`--- ${path.relative(tmp, file)}${all ? "" : " (errors, warnings, sphdeck)"}:`);
    console.error(tail(file, 30, all ? () => true : telling));
  }
  console.error(`--- code-server's log:\n${tail(path.join(tmp, "code-server.log"), 20)}`);
  console.error(`--- the browser console's errors:\n${tail(path.join(tmp, "chromium.log"), 20,
    (l) => l.includes(":CONSOLE") && /error/i.test(l))}`);
}

function stopAll() {
  for (const child of children) {
    try {
      process.kill(-child.pid, "SIGKILL"); // its process group: the extension host, the server, renderers
    } catch {
      // already gone
    }
  }
  if (process.env.SPHDECK_VSCODE_TEST_KEEP === "1") say(`kept ${tmp}`);
  else fs.rmSync(tmp, { recursive: true, force: true });
}

function finish(ok, reason) {
  if (fs.existsSync(resultFile + ".log")) process.stdout.write(fs.readFileSync(resultFile + ".log", "utf8"));
  if (!ok) {
    console.error(`vscode-test: FAILED: ${reason}`);
    printLogs();
  } else {
    say(`passed in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  }
  stopAll();
  process.exit(ok ? 0 : 1);
}

for (const [file, what] of [[sphdeck, "sphdeck"], [codeServer, "code-server (tests/editor/vscode/install.sh)"],
  [chromium, "chromium (scripts/install-deps.sh --vscode-test)"], [path.join(extensionDir, "out", "extension.js"),
    "the compiled extension (npm run compile in editors/vscode)"]]) {
  if (!fs.existsSync(file)) finish(false, `${what} not found: ${file}`);
}
setTimeout(() => finish(false, `no verdict within ${timeoutS} s`), timeoutS * 1000).unref();

// The workspace: the editor test's decks, and an empty sphdeck.toml marking the project root (the
// server then looks for including decks here only).
fs.mkdirSync(workspace);
for (const deck of ["bad_endcyc.k", "rename_main.k", "rename_section.k"]) {
  fs.copyFileSync(path.join(sourceDir, "tests", "editor", deck), path.join(workspace, deck));
}
fs.writeFileSync(path.join(workspace, "sphdeck.toml"), "");
// User settings (code-server keeps them on the server's side): the server under test, and no start page,
// trust prompt, update or gallery queries.
fs.mkdirSync(path.join(userData, "User"), { recursive: true });
fs.writeFileSync(path.join(userData, "User", "settings.json"), JSON.stringify({
  "sphdeck.path": sphdeck,
  "workbench.startupEditor": "none",
  "security.workspace.trust.enabled": false,
  "extensions.autoCheckUpdates": false,
  "extensions.autoUpdate": false,
  "telemetry.telemetryLevel": "off",
  "update.mode": "none",
}, null, 1));

async function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.on("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

function start(command, args, env, log) {
  const out = fs.openSync(path.join(tmp, log), "w");
  // detached: a process group of its own, killed whole at the end.
  const child = spawn(command, args, { env, detached: true, stdio: ["ignore", out, out] });
  children.push(child);
  child.on("exit", (code, signal) => {
    if (!fs.existsSync(resultFile)) finish(false, `${path.basename(command)} ended (code ${code}, signal ${signal}) before the verdict`);
  });
  return child;
}

function answers(url) {
  return new Promise((resolve) => {
    const request = http.get(url, (response) => {
      response.resume();
      resolve(response.statusCode < 500);
    });
    request.on("error", () => resolve(false));
    request.setTimeout(2000, () => request.destroy());
  });
}

const port = await freePort();
const authority = `127.0.0.1:${port}`;
// A private home: nothing of the machine's user is read or written.
const home = path.join(tmp, "home");
const env = {
  ...process.env, HOME: home, XDG_CONFIG_HOME: path.join(home, "config"), XDG_DATA_HOME: path.join(home, "data"),
  XDG_CACHE_HOME: path.join(home, "cache"), SPHDECK_VSCODE_TEST_RESULT: resultFile,
  SPHDECK_VSCODE_EXTENSION: extensionDir, SPHDECK_VSCODE_SERVER: sphdeck,
};
start(process.execPath, [codeServer, "--auth", "none", "--bind-addr", authority, "--disable-telemetry",
  "--disable-update-check", "--disable-workspace-trust", "--disable-getting-started-override",
  "--user-data-dir", userData, "--extensions-dir", path.join(tmp, "extensions"), "--config",
  path.join(tmp, "code-server.yaml")], env, "code-server.log");
while (!(await answers(`http://${authority}/healthz`))) {
  await new Promise((resolve) => setTimeout(resolve, 200));
}
say(`code-server answers on ${authority} after ${((Date.now() - started) / 1000).toFixed(1)} s`);

// The workbench's payload: the extension to develop and the tests to run, as URIs on the server.
const remote = (file) => `vscode-remote://${authority}${file}`;
const payload = JSON.stringify([
  ["extensionDevelopmentPath", remote(extensionDir)],
  ["extensionTestsPath", remote(path.join(here, "suite.js"))],
]);
const url = `http://${authority}/?folder=${encodeURIComponent(workspace)}&payload=${encodeURIComponent(payload)}`;
start(chromium, ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
  "--no-default-browser-check", `--user-data-dir=${path.join(tmp, "chromium")}`, "--enable-logging=stderr",
  "--v=0", url], env, "chromium.log");

while (!fs.existsSync(resultFile)) {
  await new Promise((resolve) => setTimeout(resolve, 200));
}
const verdict = JSON.parse(fs.readFileSync(resultFile, "utf8"));
finish(verdict.ok, verdict.error);
