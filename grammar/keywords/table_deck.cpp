// Deck structure keywords: *KEYWORD, *TITLE, *COMMENT, *END (lsdyna-format.md §8, §9).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

std::vector<KeywordSchema> deck_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back({
        .name = "*KEYWORD",
        .unique = true,
        // memory, memory2=, NCPU=, LONG=, I10= are arguments on the keyword line, not cards.
        .doc = "start of the deck; memory and format (long=, i10=) are given on the keyword line",
        .options =
            {
                {
                    .suffix = "ID",
                    .cards_before = {{
                        .name = "ID card",
                        .fields =
                            {
                                {.name = "PROJECT", .column = 1, .width = 20, .type = A, .doc = "project name"},
                                {.name = "NUM", .column = 21, .width = 20, .type = A, .doc = "number"},
                                {.name = "STAGE", .column = 41, .width = 40, .type = A, .doc = "stage"},
                            },
                    }},
                    .doc = "adds a card PROJECT, NUM, STAGE",
                },
                {
                    .suffix = "JOBID",
                    .cards_before = {{
                        .name = "Job id",
                        .fields = {{.name = "JBID", .column = 1, .width = 80, .type = A, .doc = "job id"}},
                    }},
                    .doc = "adds a job-id line",
                },
            },
    });
    k.push_back({
        .name = "*TITLE",
        .cards = {{
            .name = "Title",
            .fields = {{.name = "TITLE", .column = 1, .width = 80, .type = A, .doc = "title of the analysis"}},
        }},
        .unique = true,
        .doc = "one title line for the analysis",
    });
    k.push_back({
        .name = "*COMMENT",
        .cards = {{
            .name = "Text",
            .fields = {{.name = "TEXT", .column = 1, .width = 80, .type = A, .doc = "free text"}},
            .repeat = CardRepeat::Repeated,
        }},
        .doc = "free-text lines up to the next keyword (971 R6+); text after *COMMENT on its line is ignored",
        .free_text = true,
    });
    k.push_back({
        .name = "*END",
        .doc = "end of input: the rest of the file is not read",
    });
    return k;
}

}  // namespace sphdeck::keywords::tables
