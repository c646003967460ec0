// A self-contained include's reading, made once per run and laid into every deck that includes it
// (grammar/file_cache.hpp). Such a file opens no include and defines no parameter, so its blocks,
// card lines and reading findings are the same in any deck but for the file's id, where its lines
// start in the deck's list and the parameter epoch its blocks see (constant over the file).
#include "grammar/dyna/deck_reader.hpp"

namespace sphdeck::grammar::dyna {
namespace {

void move_span(Span& span, FileId from, FileId to) {
    if (span.file == from) span.file = to;
}

void move_diagnostic(diag::Diagnostic& d, FileId from, FileId to) {
    move_span(d.span, from, to);
    for (diag::Note& note : d.notes) move_span(note.span, from, to);
    for (diag::Fix& fix : d.fixes)
        for (diag::TextEdit& edit : fix.edits) move_span(edit.span, from, to);
}

}  // namespace

FileReading DeckReader::reading_of(FileId file, std::size_t first_block, std::size_t first_line,
                                   std::size_t first_diagnostic, std::uint32_t physical_lines) const {
    FileReading reading;
    reading.text = deck_.sources.file(file).text;
    reading.physical_lines = physical_lines;
    reading.lines.append(deck_.lines, first_line, deck_.lines.size(), CardLines::Move{0, 0, true, reading_file});
    reading.blocks.assign(deck_.blocks.begin() + static_cast<std::ptrdiff_t>(first_block), deck_.blocks.end());
    for (Block& block : reading.blocks) {
        block.first_line -= static_cast<std::uint32_t>(first_line);
        block.scope = 0;
        block.parameter_epoch = 0;
        block.span.file = reading_file;
    }
    reading.diagnostics.assign(deck_.diagnostics.begin() + static_cast<std::ptrdiff_t>(first_diagnostic),
                               deck_.diagnostics.end());
    for (diag::Diagnostic& d : reading.diagnostics) move_diagnostic(d, file, reading_file);
    return reading;
}

void DeckReader::lay_in(FileId file, const FileReading& reading) {
    const auto first_line = static_cast<std::uint32_t>(deck_.lines.size());
    const std::uint32_t epoch = deck_.parameters.epoch();
    deck_.lines.reserve(deck_.lines.size() + reading.lines.size());
    deck_.lines.append(reading.lines, 0, reading.lines.size(), CardLines::Move{0, 0, true, file});
    deck_.blocks.reserve(deck_.blocks.size() + reading.blocks.size());
    for (Block block : reading.blocks) {
        block.first_line += first_line;
        block.scope = file;
        block.parameter_epoch = epoch;
        block.span.file = file;
        deck_.blocks.push_back(std::move(block));
    }
    for (diag::Diagnostic d : reading.diagnostics) {
        move_diagnostic(d, reading_file, file);
        deck_.diagnostics.push_back(std::move(d));
    }
    deck_.stats.lines += reading.physical_lines;
    deck_.stats.keywords += reading.blocks.size();
    deck_.stats.cards += reading.lines.size();
}

}  // namespace sphdeck::grammar::dyna
