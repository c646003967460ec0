// fix_deck: the deck with the findings' safe fixes applied (unsafe ones on request), as the unified
// diff `sphdeck check --diff` prints, and the findings that remain. Writes the files only when asked.
#include <filesystem>
#include <fstream>

#include "edit/fix_session.hpp"
#include "edit/unified_diff.hpp"
#include "mcp/deck_input.hpp"

namespace sphdeck::mcp {
namespace {
using json = nlohmann::json;

json fix_tool_schema() {
    json properties = deck_schema_properties("deck");
    properties["unsafe"] = {{"type", "boolean"},
                            {"description", "apply the unsafe fixes too (a judgement, such as a did-you-mean name)"}};
    properties["write"] = {{"type", "boolean"},
                           {"description", "with path: write the fixed files in place (default false: only the diff)"}};
    return {{"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
}

// The path a diff header shows: relative to the working directory when inside it, as the CLI shows it.
std::string shown(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path relative = std::filesystem::proximate(path, ec);
    if (ec || relative.empty() || relative.native().starts_with("..")) return path;
    return relative.string();
}

ToolResult run_fix_tool(const Arguments& args, const ToolContext& context) {
    DeckInput deck = deck_input(args, context);
    const bool write = args.boolean("write");
    if (write && deck.from_text) throw InvalidParams("'write' needs a path: text is returned fixed instead");
    const engine::CheckOptions options = check_options(deck, context);
    const edit::FixLevel level = args.boolean("unsafe") ? edit::FixLevel::Unsafe : edit::FixLevel::Safe;
    engine::Documents documents = deck.documents;
    edit::FixOutcome outcome = edit::fix_deck(deck.path, documents, options, level);
    confine_reads(outcome.remaining, context);
    std::string diff;
    json files = json::array();
    for (const edit::FixedFile& file : outcome.files) {
        diff +=
            edit::unified_diff(shown(file.path), file.original, edit::line_edits_between(file.original, file.fixed));
        files.push_back(shown(file.path));
    }
    if (write) {
        for (const edit::FixedFile& file : outcome.files) {
            std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
            out.write(file.fixed.data(), static_cast<std::streamsize>(file.fixed.size()));
            if (!out.flush()) throw ToolFailure("cannot write " + shown(file.path));
        }
    }
    json structured = {{"fixed", outcome.fixed},
                       {"files", std::move(files)},
                       {"written", write && !outcome.files.empty()},
                       {"diff", diff},
                       {"remaining", findings_json({&outcome.remaining})}};
    if (deck.from_text) {
        const std::string* text = documents.find(std::filesystem::absolute(deck.path));
        structured["text"] = text ? *text : "";
    }
    return {std::move(structured), {}};
}
}  // namespace

Tool fix_deck_tool() {
    return {"fix_deck", "Fix a deck's mechanical mistakes",
            "Applies the fixes the findings carry (safe ones; unsafe ones too with unsafe: true) to the deck and its "
            "include files, checking again after each round, as `sphdeck check --fix` does. Returns the unified diff, "
            "the number of fixes, the findings that remain, and with text input the fixed text. Writes nothing "
            "unless write: true.",
            fix_tool_schema(), run_fix_tool};
}

}  // namespace sphdeck::mcp
