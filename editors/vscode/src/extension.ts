// Starts `sphdeck lsp` (the sphdeck language server, over stdio) for LS-DYNA and OpenRadioss decks.
// Everything the editor shows (diagnostics, hover, definitions, completion, outline, folding, code
// actions, colours by semantic tokens, inlay hints) comes from the server; this file only starts, restarts and stops it.
import * as vscode from "vscode";
import {
  LanguageClient,
  LanguageClientOptions,
  ServerOptions,
  TransportKind,
} from "vscode-languageclient/node";

let client: LanguageClient | undefined;

function serverOptions(): ServerOptions {
  const config = vscode.workspace.getConfiguration("sphdeck");
  const command = config.get<string>("path", "sphdeck") || "sphdeck";
  const args = ["lsp", ...config.get<string[]>("extraArgs", [])];
  return {
    run: { command, args, transport: TransportKind.stdio },
    debug: { command, args, transport: TransportKind.stdio },
  };
}

function clientOptions(): LanguageClientOptions {
  const inlayHints = vscode.workspace.getConfiguration("sphdeck").get<object>("inlayHints", {});
  return {
    // Inlay hint settings (bulkBlocks, defaults, parameterValues): at start, then on every change.
    initializationOptions: { inlayHints },
    // .inc files belong to either dialect: the server tells them apart by their content.
    documentSelector: [
      { scheme: "file", language: "lsdyna" },
      { scheme: "file", language: "openradioss" },
      { scheme: "file", pattern: "**/*.inc" },
      { scheme: "untitled", language: "lsdyna" },
      { scheme: "untitled", language: "openradioss" },
    ],
    synchronize: {
      configurationSection: "sphdeck",
      // The project's configuration and the files decks include, edited outside the editor.
      fileEvents: vscode.workspace.createFileSystemWatcher("**/{sphdeck.toml,*.k,*.key,*.dyn,*.inc,*.rad}"),
    },
  };
}

async function start(context: vscode.ExtensionContext): Promise<void> {
  client = new LanguageClient("sphdeck", "sphdeck", serverOptions(), clientOptions());
  try {
    await client.start();
  } catch (error) {
    const command = vscode.workspace.getConfiguration("sphdeck").get<string>("path", "sphdeck");
    void vscode.window.showErrorMessage(
      `sphdeck: could not start '${command} lsp' (set "sphdeck.path"): ${String(error)}`,
    );
  }
  context.subscriptions.push({ dispose: () => void client?.stop() });
}

async function restart(context: vscode.ExtensionContext): Promise<void> {
  if (client) {
    await client.stop();
    client = undefined;
  }
  await start(context);
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  context.subscriptions.push(
    vscode.commands.registerCommand("sphdeck.restartServer", () => restart(context)),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (event.affectsConfiguration("sphdeck.path") || event.affectsConfiguration("sphdeck.extraArgs")) {
        void restart(context);
      }
    }),
  );
  await start(context);
}

export async function deactivate(): Promise<void> {
  if (client) {
    await client.stop();
    client = undefined;
  }
}
