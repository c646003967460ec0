// textDocument/documentLink: each *INCLUDE (*INCLUDE_PATH resolved) file name and Radioss #include of a
// file links to the file the check opened for it (the reader resolved it: grammar/file_paths.hpp), so
// the link goes where the checker read, not where a client would guess.
#include <string_view>

#include "grammar/fields.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {
namespace {

bool starts_with_no_case(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
    return true;
}

// The file name's bytes on an include line: the trimmed line, after "#include" on a Radioss line.
grammar::Span name_span(std::string_view text, grammar::FileId file, std::uint32_t line) {
    std::size_t from = text.find_first_not_of(" \t");
    if (from == std::string_view::npos) return {};
    if (starts_with_no_case(text.substr(from), "#include")) {
        from = text.find_first_not_of(" \t", from + 8);
        if (from == std::string_view::npos) return {};
    }
    const std::string_view name = grammar::trim_blanks(text.substr(from));
    if (name.empty()) return {};
    return {file, line, static_cast<std::uint32_t>(from + 1), static_cast<std::uint32_t>(from + name.size() + 1)};
}

}  // namespace

nlohmann::json document_links(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    nlohmann::json out = nlohmann::json::array();
    const auto& sources = deck.result.deck.sources;
    if (file >= sources.size()) return out;
    for (grammar::FileId child = 0; child < sources.size(); ++child) {
        const grammar::SourceFile& f = sources.file(child);
        if (f.parent != file || f.include_line == 0) continue;
        const grammar::Span span = name_span(sources.line_text(file, f.include_line), file, f.include_line);
        if (!span.valid()) continue;
        const std::string target = uri_from_path(f.path);
        out.push_back({{"range", range_json(sources, span)}, {"target", target}, {"tooltip", f.path}});
    }
    return out;
}

}  // namespace sphdeck::lsp
