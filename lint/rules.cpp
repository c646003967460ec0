#include "lint/rules.hpp"

namespace sphdeck::lint {

void run_rules(RuleContext& context) {
    check_references(context);
}

}  // namespace sphdeck::lint
