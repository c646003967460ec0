#include "grammar/read_deck.hpp"

#include <stdexcept>

#include "grammar/deck_files.hpp"
#include "grammar/radioss/reader.hpp"
#include "text/text_file.hpp"

namespace sphdeck::grammar {
namespace {
// A Radioss main file may hold nothing but #include lines: when those fail, their DK010 says
// why the deck is empty, and the deck is not "not a deck".
bool names_includes(const RawDeck& deck) {
    if (deck.sources.size() > 1) return true;
    for (const diag::Diagnostic& d : deck.diagnostics)
        if (d.code == "DK010" || d.code == "DK011" || d.code == "DK025") return true;
    return false;
}
}  // namespace

std::string_view to_string(DeckFormat f) { return f == DeckFormat::Radioss ? "radioss" : "ls-dyna"; }

DeckFormat detect_format(std::string_view text, std::string_view file_name) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    // Decks of millions of lines decide in their first lines: look at the first 200 at most.
    for (int n = 0; n < 200 && !text.empty(); ++n) {
        std::size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (line.rfind("#RADIOSS", 0) == 0) return DeckFormat::Radioss;
        std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string_view::npos || line[0] == '$' || line[0] == '#') continue;
        if (line[first] == '*') return DeckFormat::LsDyna;
        if (line[first] == '/') return DeckFormat::Radioss;
        break;
    }
    return file_name.ends_with(radioss_deck_extension) ? DeckFormat::Radioss : DeckFormat::LsDyna;
}

DeckFormat format_of(const RawDeck& deck) {
    for (const Block& b : deck.blocks) return b.keyword.rfind('/', 0) == 0 ? DeckFormat::Radioss : DeckFormat::LsDyna;
    if (deck.sources.size() == 0) return DeckFormat::LsDyna;
    return detect_format(deck.sources.file(0).text, deck.sources.file(0).display_name);
}

RawDeck read_deck(const std::string& path, const dyna::ReaderOptions& options, std::optional<DeckFormat> format) {
    // The first bytes tell the format and whether this is text at all: a binary file is refused
    // before the line grammar walks through gigabytes of it.
    const std::string prefix = read_file_prefix(path, 64 * 1024, options.overlay);
    if (auto why = text::binary_or_empty(prefix))
        throw std::runtime_error("'" + path + "' is not a keyword deck: " + *why);
    if (!format) format = detect_format(prefix, path);
    RawDeck deck = *format == DeckFormat::Radioss ? radioss::read_file(path, options) : dyna::read_file(path, options);
    if (deck.blocks.empty() && !names_includes(deck)) {
        const char* what =
            *format == DeckFormat::Radioss ? "header line (/BEGIN, /NODE...)" : "keyword line (*NODE, *PART...)";
        throw std::runtime_error("'" + path + "' is not a keyword deck: no " + what + " in it");
    }
    return deck;
}

RawDeck read_deck_buffer(std::string text, const std::string& display_name, const std::string& base_directory,
                         const dyna::ReaderOptions& options, std::optional<DeckFormat> format) {
    const DeckFormat f = format.value_or(detect_format(text, display_name));
    return f == DeckFormat::Radioss ? radioss::read_buffer(std::move(text), display_name, base_directory, options)
                                    : dyna::read_buffer(std::move(text), display_name, base_directory, options);
}

}  // namespace sphdeck::grammar
