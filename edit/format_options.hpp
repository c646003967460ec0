// What `sphdeck format` (and the editor's formatting requests) are asked to do.
#pragma once

namespace sphdeck::edit {

struct FormatOptions {
    bool headers = false;   // a `$#` line naming the fields above each card (LS-DYNA), as LS-PrePost writes it
    bool to_fixed = false;  // free (comma) lines rewritten in fixed columns when every value fits
    bool includes = false;  // format the included files too (else only the deck's own file)
};

}  // namespace sphdeck::edit
