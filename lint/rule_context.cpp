#include "lint/rule_context.hpp"

#include "lint/registry.hpp"

namespace sphdeck::lint {

diag::Diagnostic& RuleContext::report(std::string_view code, grammar::Span span, std::string message) {
    const RuleInfo* rule = find_rule(code);
    return report(code, rule ? rule->severity : diag::Severity::Warning, span, std::move(message));
}

diag::Diagnostic& RuleContext::report(std::string_view code, diag::Severity severity, grammar::Span span,
                                      std::string message) {
    out_.push_back(diag::Diagnostic{std::string(code), severity, std::move(message), span, {}});
    return out_.back();
}

namespace {
grammar::Span whole_line(const grammar::RawDeck& deck, std::uint32_t index) {
    if (index >= deck.lines.size()) return {};
    const grammar::CardLine& l = deck.lines[index];
    return grammar::Span{l.file, l.line, 1, l.length + 1};
}
}  // namespace

grammar::Span RuleContext::particle_span(std::size_t particle) const {
    return whole_line(deck, model.particles.line.at(particle));
}

grammar::Span RuleContext::node_span(std::size_t node) const { return whole_line(deck, model.nodes.line.at(node)); }

}  // namespace sphdeck::lint
