// The registry as the data diag/'s reports print: every rule's code, name, level, summary and
// documentation (text, Markdown, URL). Built once, on first use.
#pragma once

#include "diag/rule_catalog.hpp"

namespace sphdeck::lint {

const diag::RuleCatalog& rule_catalog();

}  // namespace sphdeck::lint
