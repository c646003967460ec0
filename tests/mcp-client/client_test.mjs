// `sphdeck mcp` under the official MCP TypeScript SDK's client (@modelcontextprotocol/sdk, the version
// package-lock.json pins): initialize with the roots capability, list the tools, call each on shipped
// decks and check what comes back; then the errors: an unknown tool, a path outside the roots, and
// malformed requests written straight to the server's standard input.
//   node client_test.mjs SPHDECK_BINARY SOURCE_DIR
import assert from "node:assert/strict";
import { spawn } from "node:child_process";
import { pathToFileURL } from "node:url";
import path from "node:path";
import { createInterface } from "node:readline";

import { Client } from "@modelcontextprotocol/sdk/client/index.js";
import { StdioClientTransport } from "@modelcontextprotocol/sdk/client/stdio.js";
import { ListRootsRequestSchema, McpError } from "@modelcontextprotocol/sdk/types.js";

const [sphdeck, source] = process.argv.slice(2).map((p) => path.resolve(p));
const decks = path.join(source, "decks");
const mistakes = "demo/sph_mistakes_2d.k";
const column = "run/water_column_2d.k";
let checks = 0;

function check(condition, message) {
  assert.ok(condition, message);
  ++checks;
}

async function rejectsWith(promise, code, fragment) {
  try {
    await promise;
  } catch (e) {
    check(e instanceof McpError, `an McpError, not ${e}`);
    check(e.code === code, `error code ${e.code}, expected ${code}: ${e.message}`);
    check(e.message.includes(fragment), `"${fragment}" in "${e.message}"`);
    return;
  }
  assert.fail(`expected an error ${code}`);
}

async function sdkClient() {
  const client = new Client({ name: "sphdeck-test", version: "1.0.0" }, { capabilities: { roots: {} } });
  // The root is decks/: the server confines every path to it.
  client.setRequestHandler(ListRootsRequestSchema, async () => ({
    roots: [{ uri: pathToFileURL(decks).href, name: "decks" }],
  }));
  const transport = new StdioClientTransport({ command: sphdeck, args: ["mcp"], cwd: source, stderr: "pipe" });
  await client.connect(transport);
  check(client.getServerVersion().name === "sphdeck", "server name");

  const { tools } = await client.listTools();
  const names = tools.map((t) => t.name).sort();
  assert.deepEqual(names, ["check_deck", "diff_decks", "explain_rule", "fix_deck", "format_deck",
                           "keyword_layout", "smoothing_preview"]);
  for (const t of tools) check(t.inputSchema.type === "object" && t.description.length > 0, t.name);

  const call = async (name, args) => {
    const result = await client.callTool({ name, arguments: args });
    check(result.isError === false, `${name}: ${JSON.stringify(result.content)}`);
    check(result.content[0].type === "text", `${name}: text content`);
    return result.structuredContent;
  };

  const checked = await call("check_deck", { path: mistakes });
  const codes = checked.diagnostics.map((d) => `${d.code}:${d.line}`);
  assert.deepEqual(codes, ["SPH010:15", "SPH030:20", "SPH100:26", "REF003:38"]);
  const sph030 = checked.diagnostics[1];
  check(sph030.severity === "error" && sph030.column > 0 && sph030.file.endsWith("sph_mistakes_2d.k"), "located");

  const fixed = await call("fix_deck", { text: "*KEYWORD\n*control_termination\n       1.0\n*END\n" });
  check(fixed.fixed >= 1 && fixed.diff.includes("+*CONTROL_TERMINATION"), "fix diff");

  const formatted = await call("format_deck", { path: column });
  check(formatted.changed === false, "a shipped deck is formatted");

  const rule = await call("explain_rule", { rule: "SPH030" });
  check(rule.code === "SPH030" && rule.page.includes("SPH030"), "rule page");

  const layout = await call("keyword_layout", { name: "*SECTION_SPH" });
  check(layout.cards[0].fields.some((f) => f.name === "CSLH"), "CSLH in *SECTION_SPH");

  const preview = await call("smoothing_preview", { path: column });
  check(preview.parts.length > 0 && preview.parts[0].h0 > 0, "h0 per part");

  const diff = await call("diff_decks", { before: mistakes, after: column });
  check(diff.equal === false && diff.keywords.length > 0, "the decks differ");

  await rejectsWith(client.callTool({ name: "no_such_tool", arguments: {} }), -32602, "unknown tool");
  await rejectsWith(client.callTool({ name: "check_deck", arguments: { path: path.join(source, "README.md") } }),
                    -32602, "outside the roots");
  await rejectsWith(client.callTool({ name: "check_deck", arguments: { path: "../README.md" } }), -32602,
                    "outside the roots");
  await rejectsWith(client.callTool({ name: "check_deck", arguments: { path: 3 } }), -32602, "type string");
  await client.close();
}

// Malformed requests no SDK would send, written to the server's standard input line by line.
async function rawLines() {
  const server = spawn(sphdeck, ["mcp"], { cwd: source, stdio: ["pipe", "pipe", "ignore"] });
  const lines = createInterface({ input: server.stdout });
  const answers = [];
  lines.on("line", (line) => answers.push(JSON.parse(line)));
  const closed = new Promise((resolve) => server.on("close", resolve));
  server.stdin.write('{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"protocolVersion":"2025-06-18",' +
                     '"capabilities":{},"clientInfo":{"name":"raw","version":"1"}}}\n');
  server.stdin.write("{this is not json\n");
  server.stdin.write('{"jsonrpc":"2.0","id":2}\n');
  server.stdin.write('{"jsonrpc":"2.0","id":3,"method":"tools/call","params":"check_deck"}\n');
  server.stdin.write('{"jsonrpc":"2.0","id":4,"method":"no/such/method"}\n');
  server.stdin.end();
  await closed;
  assert.equal(answers.length, 5);
  check(answers[1].error.code === -32700 && answers[1].id === null, "parse error");
  check(answers[2].error.code === -32600 && answers[2].id === 2, "no method");
  check(answers[3].error.code === -32600 && answers[3].id === 3, "params not an object");
  check(answers[4].error.code === -32601, "unknown method");
}

await sdkClient();
await rawLines();
const sdk = JSON.parse(
  await import("node:fs").then((fs) =>
    fs.promises.readFile(new URL("./node_modules/@modelcontextprotocol/sdk/package.json", import.meta.url)))).version;
console.log(`mcp client test: ${checks} checks passed (@modelcontextprotocol/sdk ${sdk})`);
