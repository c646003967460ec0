// The lint rule families (design.md: one file per family), each a function of the context.
#pragma once

#include "lint/rule_context.hpp"

namespace sphdeck::lint {

void check_references(RuleContext& c);  // rules_references.cpp: REF001-REF008

}  // namespace sphdeck::lint
