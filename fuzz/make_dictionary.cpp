// Prints a libFuzzer dictionary for one target (fuzz_dictionary TARGET > TARGET.dict): the
// keyword names and options of the schema tables, so the dictionary never lags behind them,
// plus the reader's own tokens.
#include <cstdio>
#include <set>
#include <string>
#include <string_view>

#include "grammar/keywords/schema.hpp"
#include "grammar/radioss/cards.hpp"

namespace {

void dyna(std::set<std::string>& out) {
    for (const auto& k : sphdeck::keywords::all_keywords()) {
        out.emplace(k.name);
        for (auto alias : k.aliases) out.emplace(alias);
        for (const auto& o : k.options) out.emplace("_" + std::string(o.suffix));
        for (const auto& card : k.cards)
            for (const auto& f : card.fields) out.emplace(f.name);
    }
    for (const char* token : {"*KEYWORD",
                              "*END",
                              "*INCLUDE",
                              "*INCLUDE_PATH",
                              "*INCLUDE_PATH_RELATIVE",
                              "*INCLUDE_TRANSFORM",
                              "*PARAMETER",
                              "*PARAMETER_EXPRESSION",
                              "*PARAMETER_LOCAL",
                              "*PARAMETER_DUPLICATION",
                              "*COMMENT",
                              "*TITLE",
                              "&",
                              "-&",
                              "$",
                              "$#",
                              ",",
                              " +",
                              "long=y",
                              "i10=y",
                              "memory2=",
                              "1e15",
                              "1e300",
                              "-1e300",
                              "nan",
                              "inf",
                              "1.0D+00",
                              "-BEGIN PGP MESSAGE-",
                              "-END PGP MESSAGE-",
                              "$ sphdeck: disable=",
                              "$ sphdeck: disable-next-line=",
                              "$ sphdeck: enable=",
                              " -- ",
                              "         1"})
        out.emplace(token);
}

void radioss(std::set<std::string>& out) {
    for (const auto& k : sphdeck::grammar::radioss::all_keywords()) {
        out.emplace(k.name);
        for (auto alias : k.aliases) out.emplace(alias);
    }
    for (const char* token : {"#RADIOSS STARTER",
                              "/BEGIN",
                              "/END",
                              "#include",
                              "#enddata",
                              "/PARAMETER/GLOBAL/REAL",
                              "/PARAMETER/GLOBAL/INTEGER",
                              "/PARAMETER/LOCAL",
                              "[",
                              "]",
                              "#",
                              "#-",
                              "2026",
                              "2024",
                              "44",
                              "1e15",
                              "1e300",
                              "nan",
                              "                   1",
                              "# sphdeck: disable=",
                              "# sphdeck: disable-next-line="})
        out.emplace(token);
}

void expression(std::set<std::string>& out) {
    for (const char* token :
         {"sin(",  "cos(",   "tan(", "asin(", "acos(", "atan(",    "atan2(", "sqrt(", "abs(", "exp(",
          "log(",  "log10(", "min(", "max(",  "int(",  "nint(",    "pi",     "**",    "&a",   "&big",
          "&zero", "&tiny",  "&neg", "&inf",  "1e308", "1.0D+300", "(",      ")",     ","})
        out.emplace(token);
}

void keyword_arguments(std::set<std::string>& out) {
    for (const char* token : {"memory=", "memory2=", "ncpu=", "long=y", "long=s", "i10=y", "m", "mw", "g", "k", "100m",
                              "9999999999999999999", "="})
        out.emplace(token);
}

void lsp_messages(std::set<std::string>& out) {
    for (const char* token : {"Content-Length: ", "Content-Type: application/vscode-jsonrpc; charset=utf-8", "\r\n",
                              "\r\n\r\n", "{\"jsonrpc\":\"2.0\",",
                              "\"id\":", "\"method\":", "\"params\":", "\"initialize\"", "\"textDocument/didChange\"",
                              "\"contentChanges\"", "\"range\"", "[", "]", "{", "}", "\\u00e9", "99999999999999999999"})
        out.emplace(token);
}

// A dictionary entry: the token in double quotes, with quote, backslash and bytes outside
// printable ASCII written as \xNN.
void print(std::string_view token) {
    std::fputc('"', stdout);
    for (unsigned char c : token) {
        if (c == '"' || c == '\\' || c < 0x20 || c > 0x7e)
            std::printf("\\x%02X", c);
        else
            std::fputc(c, stdout);
    }
    std::fputs("\"\n", stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string_view target = argc > 1 ? argv[1] : "";
    std::set<std::string> tokens;
    // dyna_read and format_dyna read LS-DYNA decks as dyna_check does: the same words.
    if (target == "dyna_check" || target == "dyna_read" || target == "format_dyna")
        dyna(tokens), expression(tokens), keyword_arguments(tokens);
    else if (target == "radioss_check" || target == "radioss_read")
        radioss(tokens);
    else if (target == "expression")
        expression(tokens);
    else if (target == "keyword_arguments")
        keyword_arguments(tokens);
    else if (target == "lsp_messages")
        lsp_messages(tokens);
    else {
        std::fprintf(stderr,
                     "usage: fuzz_dictionary dyna_read|dyna_check|format_dyna|radioss_read|radioss_check|"
                     "expression|keyword_arguments|lsp_messages\n");
        return 2;
    }
    tokens.erase("");
    for (const std::string& t : tokens) print(t);
    return 0;
}
