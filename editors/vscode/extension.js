// Starts `durer lsp` for POV-Ray files. Install: `npm install` here, then
// `npx @vscode/vsce package` and install the .vsix (or open this folder and press F5).
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate() {
  const config = vscode.workspace.getConfiguration("durer");
  const command = config.get("path", "durer");
  client = new LanguageClient(
    "durer",
    "durer",
    { run: { command, args: ["lsp"] }, debug: { command, args: ["lsp"] } },
    {
      documentSelector: [{ scheme: "file", language: "povray" }, { scheme: "untitled", language: "povray" }],
      initializationOptions: { library: config.get("library", []) },
    }
  );
  client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
