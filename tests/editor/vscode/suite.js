// The VS Code extension's test (issue 45), run by VS Code's extension host as its extensionTestsPath:
// the extension (editors/vscode, loaded as the development extension) starts `sphdeck lsp` through
// vscode-languageclient, and everything below goes through VS Code's own API and commands, as the
// editor's features do. driver.mjs starts VS Code (code-server) with a workspace holding copies of
// tests/editor/*.k and the setting sphdeck.path; this module writes its progress to RESULT.log and its
// verdict to RESULT (a JSON {ok, error}), which the driver waits for: the browser window's end of the
// test is not seen by the driver. Every wait is bounded; the driver bounds the whole run.
"use strict";
const fs = require("fs");
const path = require("path");
const vscode = require("vscode");

const resultFile = process.env.SPHDECK_VSCODE_TEST_RESULT;
const waitMs = Number(process.env.SPHDECK_VSCODE_TEST_WAIT_MS || 30000);

function say(text) {
  fs.appendFileSync(resultFile + ".log", `vscode-test: ${text}\n`);
}

class CheckFailed extends Error {}
function check(condition, what) {
  if (!condition) throw new CheckFailed(what);
}
const show = (value) => JSON.stringify(value, null, 1);

// Polls `probe` until it returns something truthy (returned), or fails naming `what`.
async function waitFor(what, probe) {
  const end = Date.now() + waitMs;
  for (;;) {
    const value = await probe();
    if (value) return value;
    if (Date.now() > end) throw new CheckFailed(`timed out after ${waitMs} ms waiting for ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}

function codeOf(diagnostic) {
  return typeof diagnostic.code === "object" ? diagnostic.code.value : diagnostic.code;
}

async function open(file) {
  const document = await vscode.workspace.openTextDocument(vscode.Uri.file(file));
  await vscode.window.showTextDocument(document);
  return document;
}

async function checks() {
  const folder = vscode.workspace.workspaceFolders && vscode.workspace.workspaceFolders[0];
  check(folder, "VS Code opened no workspace folder");
  const dir = folder.uri.fsPath;
  say(`VS Code ${vscode.version}, workspace ${dir}`);
  const extension = vscode.extensions.getExtension("sphdeck.sphdeck");
  check(extension, "the extension sphdeck.sphdeck is not loaded");
  check(extension.extensionPath === process.env.SPHDECK_VSCODE_EXTENSION,
    `the extension loaded is ${extension.extensionPath}, not ${process.env.SPHDECK_VSCODE_EXTENSION}`);
  const configured = vscode.workspace.getConfiguration("sphdeck").get("path");
  check(configured === process.env.SPHDECK_VSCODE_SERVER, `sphdeck.path is ${configured}, not the server under test`);

  // 1. Diagnostics: DK002 on tests/editor/bad_endcyc.k (ENDCYC typed 10000O), line 6 column 15; it goes
  // once the line is fixed through an edit (didChange).
  const bad = await open(path.join(dir, "bad_endcyc.k"));
  check(bad.languageId === "lsdyna", `bad_endcyc.k has language ${bad.languageId}, expected lsdyna`);
  await waitFor("the extension to activate", () => extension.isActive);
  say("extension active");
  const dk002 = () => vscode.languages.getDiagnostics(bad.uri).find((d) => codeOf(d) === "DK002");
  const finding = await waitFor("the DK002 diagnostic of bad_endcyc.k", dk002);
  check(finding.range.start.line === 5 && finding.range.start.character === 14,
    `DK002 at ${finding.range.start.line}:${finding.range.start.character} (0-based), expected 5:14`);
  check(finding.severity === vscode.DiagnosticSeverity.Error, `DK002 severity ${finding.severity}, expected Error`);
  check(finding.message.includes("10000O"), `DK002 message does not quote the value: ${finding.message}`);
  say(`diagnostic: ${finding.message}`);
  const fix = new vscode.WorkspaceEdit();
  fix.replace(bad.uri, bad.lineAt(5).range, "     0.002     10000");
  check(await vscode.workspace.applyEdit(fix), "the fix of line 6 was not applied");
  await waitFor("the DK002 diagnostic to go after the fix", () => !dk002());
  say("diagnostic gone after the edit");

  // 2. The deck with an include (tests/editor/rename_main.k includes rename_section.k).
  const mainFile = path.join(dir, "rename_main.k");
  const sectionFile = path.join(dir, "rename_section.k");
  const mainText = fs.readFileSync(mainFile, "utf8");
  const sectionText = fs.readFileSync(sectionFile, "utf8");
  const main = await open(mainFile);
  const mainUri = main.uri;

  const links = await vscode.commands.executeCommand("vscode.executeLinkProvider", mainUri, 10);
  check(links.length === 1 && links[0].target && links[0].target.fsPath === sectionFile &&
        links[0].range.start.line === 4,
    `document links of rename_main.k, expected one on line 5 to ${sectionFile}: ${show(links)}`);
  say(`document link: line 5 -> ${links[0].target.toString()}`);

  const symbols = await vscode.commands.executeCommand("vscode.executeWorkspaceSymbolProvider", "sect");
  check(symbols.some((s) => s.name === "SECTION 3" && s.location.uri.fsPath === sectionFile),
    `workspace symbols for 'sect' do not list SECTION 3 of the include: ${show(symbols)}`);
  say(`workspace symbols: ${symbols.length} for 'sect', SECTION 3 in rename_section.k among them`);

  // Code lenses, resolved: PART 1 (used by nothing), MAT 5 (used by part 1), in the order of the deck.
  const lenses = await vscode.commands.executeCommand("vscode.executeCodeLensProvider", mainUri, 10);
  lenses.sort((a, b) => a.range.start.line - b.range.start.line);
  const titles = lenses.map((l) => (l.command ? l.command.title : "?"));
  check(titles.length === 2 && titles[0] === "used by 0" && titles[1] === "used by 1",
    `code lenses of rename_main.k (PART 1, MAT 5), expected "used by 0", "used by 1": ${show(titles)}`);
  say(`code lens: ${titles.join(", ")} (lines ${lenses.map((l) => l.range.start.line + 1).join(", ")})`);

  // Rename section 3 (the SECID of part 1, line 9, columns 11-20) across the include.
  const secid = new vscode.Position(8, 19);
  const prepared = await vscode.commands.executeCommand("vscode.prepareRename", mainUri, secid);
  // The server's range: the id's own characters in its right-aligned field, and the id as placeholder.
  check(prepared && prepared.range.isEqual(new vscode.Range(8, 19, 8, 20)) && prepared.placeholder === "3",
    `prepareRename on the SECID of part 1, expected line 9 characters 19-20, placeholder 3: ${show(prepared)}`);
  say(`prepare rename: line 9, characters ${prepared.range.start.character}-${prepared.range.end.character}`);

  let refusal = null;
  try {
    await vscode.commands.executeCommand("vscode.executeDocumentRenameProvider", mainUri, secid, "12345678901");
  } catch (error) {
    refusal = String(error && error.message ? error.message : error);
  }
  check(refusal && refusal.includes("does not fit the 10-column field SECID"),
    `an id too wide for its field was not refused with its reason: ${refusal}`);
  say(`rename refused: ${refusal}`);

  const edit = await vscode.commands.executeCommand("vscode.executeDocumentRenameProvider", mainUri, secid, "42");
  check(edit, "the rename to 42 gave no edit");
  const entries = edit.entries();
  const byFile = new Map(entries.map(([uri, edits]) => [uri.fsPath, edits]));
  check(entries.length === 2 && byFile.has(mainFile) && byFile.has(sectionFile),
    `the rename edits ${show(entries.map(([uri]) => uri.fsPath))}, expected rename_main.k and rename_section.k`);
  // Only the id fields: SECID of part 1 (line 9, columns 11-20), SECID of *SECTION_SPH (line 4, 1-10).
  const inField = (edits, line, first, last) => edits.length === 1 && edits[0].range.isSingleLine &&
    edits[0].range.start.line === line && edits[0].range.start.character >= first &&
    edits[0].range.end.character <= last && edits[0].newText.trim() === "42";
  check(inField(byFile.get(mainFile), 8, 10, 20), `rename's edit of rename_main.k: ${show(byFile.get(mainFile))}`);
  check(inField(byFile.get(sectionFile), 3, 0, 10), `rename's edit of rename_section.k: ${show(byFile.get(sectionFile))}`);
  check(await vscode.workspace.applyEdit(edit), "the rename's edit was not applied");
  const section = await vscode.workspace.openTextDocument(vscode.Uri.file(sectionFile));
  const replaceLine = (text, line, by) => text.split("\n").map((l, i) => (i === line ? by : l)).join("\n");
  const expectedMain = replaceLine(mainText, 8, "         1        42         5");
  const expectedSection = replaceLine(sectionText, 3, "        42       1.2");
  check(main.getText() === expectedMain, `rename_main.k after the rename:\n${main.getText()}`);
  check(section.getText() === expectedSection, `rename_section.k after the rename:\n${section.getText()}`);
  say("renamed section 3 to 42 in rename_main.k and its include (applied, unsaved)");
}

exports.run = async function run() {
  const started = Date.now();
  let verdict;
  try {
    await checks();
    verdict = { ok: true };
    say(`passed in ${Date.now() - started} ms`);
  } catch (error) {
    verdict = { ok: false, error: error instanceof CheckFailed ? error.message : String(error && error.stack) };
  }
  // Written whole, then renamed: the driver never reads half a verdict.
  fs.writeFileSync(resultFile + ".part", JSON.stringify(verdict));
  fs.renameSync(resultFile + ".part", resultFile);
};
