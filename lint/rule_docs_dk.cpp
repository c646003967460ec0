// DK rules: deck syntax and card values, found by the readers and the schemas.
// One row per rule: code, name, default severity, since-version, source, summary and the
// documentation `sphdeck rule CODE` prints (what / why / fix / before / after).
// The deck snippets are column-exact: keep fields aligned when editing them.
#include "lint/registry.hpp"

namespace sphdeck::lint::detail {
namespace {

constexpr RuleInfo kDkRules[] = {
    // DK001 unknown-keyword
    {.code = "DK001",
     .name = "unknown-keyword",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "schema",
     .summary = "keyword unknown to the schema: kept as opaque text and counted, never an error",
     .doc = {.what = "Reports a keyword that sphdeck's schema does not describe. Its cards are "
                     "kept as opaque text, counted in the summary and not checked. This is never "
                     "an error: the keyword may be perfectly valid for the solver.",
             .why = "sphdeck decodes the keywords SPH decks rely on, not the whole LS-DYNA "
                    "manual, so an unknown name is often legitimate. It is also how a misspelt "
                    "keyword shows up: the solver then rejects it or, in OpenRadioss's LS-DYNA "
                    "reader, which looks names up exactly, drops it with all its cards, and the "
                    "settings in it never reach the model (LS-DYNA keyword names and options).",
             .fix = "Compare the name with the manual; sphdeck suggests close known names. If the "
                    "keyword is correct, nothing needs to change: silence it with `$ sphdeck: "
                    "disable=DK001` if it is noise.",
             .before = R"deck(*CONTROL_SPHH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK002 bad-integer
    {.code = "DK002",
     .name = "bad-integer",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "text in an integer field that is not an integer (after parameter substitution)",
     .doc = {.what = "Reports an integer (I) field whose text, after `&name` parameters are "
                     "substituted, is not an integer: letters, units, two values run together, or "
                     "a value shifted into the wrong columns.",
             .why = "Cards are read by fixed column ranges, and an integer field must hold an "
                    "integer; the solver stops at input when it cannot read one (LS-DYNA manual, "
                    "general card format; OpenRadioss reader message 100101). A field that "
                    "\"looks\" right is often a neighbour's value that slid across a column "
                    "boundary.",
             .fix = "Write a plain integer inside the field's columns (right-aligned by "
                    "convention). If the text is a parameter, check that it is an I parameter.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20        3D       150         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK003 bad-real
    {.code = "DK003",
     .name = "bad-real",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "text in a real field that is not a real number (Fortran forms such as 1.0+3 and "
                "2.5D-4 are valid)",
     .doc = {.what = "Reports a real (F) field whose text is not a number. Fortran forms are "
                     "accepted: `5`, `.5`, `1.0e3`, `2.5D-4`, and an exponent without its letter "
                     "such as `1.0+3` (= 1000) or `3.5-10`.",
             .why = "The solver cannot read the card and stops at input (LS-DYNA manual, general "
                    "card format; OpenRadioss reader message 100102). Typical causes are a unit "
                    "written after the value, a letter O typed for a zero, or a decimal comma, "
                    "which also switches the line to free format.",
             .fix = "Write the bare number in the deck's unit system, without unit text.",
             .before = R"deck(*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
    10.0ms         0       0.0       0.0    1.0e+8         0
)deck",
             .after = R"deck(*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     0.010         0       0.0       0.0    1.0e+8         0
)deck"}},

    // DK004 integer-as-real
    {.code = "DK004",
     .name = "integer-as-real",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "an integral real such as 1.0 or 1e3 in an integer field: accepted as the "
                "integer, flagged",
     .doc = {.what = "Reports an integer field holding an integral real such as `1.0` or `1e3`. "
                     "sphdeck reads it as the integer; a non-integral value such as `1.5` is a "
                     "DK002 error instead.",
             .why = "The manual types these fields as integers and does not say what happens to a "
                    "real in them; readers differ, from converting it through a real to "
                    "misreading `1.0` as 10 (LS-DYNA manual, general card format: I and F field "
                    "types). An integer removes the doubt.",
             .fix = "Write the integer: `3` instead of `3.0`.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20       3.0       150       1.0       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK005 free-token-too-long
    {.code = "DK005",
     .name = "free-token-too-long",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a comma-separated value longer than the fixed width of its field",
     .doc = {.what = "In a card written in free (comma-separated) format, reports a value with "
                     "more characters than the field has columns in fixed format, e.g. a "
                     "19-character coordinate in the 16-wide X of *NODE.",
             .why = "Free format does not lift the width limits: each value may use at most as "
                    "many characters as its field has in fixed format, so an 8-wide id cannot "
                    "exceed 99999999 (LS-DYNA manual, general card format, free format). A longer "
                    "value is cut or rejected, and a cut coordinate silently moves the particle.",
             .fix = "Shorten the value to the field width, dropping insignificant digits (or use "
                    "the long format for the keyword if the digits matter).",
             .before = R"deck(*NODE
$#   nid               x               y               z      tc      rc
101,-12.345678901234567,0.0,0.0
)deck",
             .after = R"deck(*NODE
$#   nid               x               y               z      tc      rc
101,-12.3456789012,0.0,0.0
)deck"}},

    // DK006 beyond-last-column
    {.code = "DK006",
     .name = "beyond-last-column",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "non-blank text past column 80 (160 or 200 in long format), which the solver "
                "ignores",
     .doc = {.what = "Reports non-blank text beyond the last significant column of a data line: "
                     "column 80 in standard and I10 format, 160 or 200 in long format.",
             .why = "The solver reads only the significant width of a card and silently ignores "
                    "the rest (LS-DYNA manual, general card format). Text there is usually a "
                    "value that slipped one field to the right, so the field it was meant for "
                    "keeps its default.",
             .fix = "Move the value into its field, or delete the trailing text; put remarks on a "
                    "`$` comment line.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0              1000.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0    1000.0
)deck"}},

    // DK007 value-out-of-range
    {.code = "DK007",
     .name = "value-out-of-range",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "schema",
     .summary = "a value outside the field's allowed values or range (e.g. FORM 11, IDIM 1, INI 3)",
     .doc = {.what = "Reports a value that is not one of the field's enumerated values or lies "
                     "outside its range, for example FORM 11, IDIM 1 or INI 3 on *CONTROL_SPH.",
             .why = "Only the listed values have a meaning: *CONTROL_SPH defines FORM 0-10, 12, "
                    "15 and 16 (13 in newer editions), IDIM 3, 2 or -2 and INI 0-2, and nothing "
                    "else (*CONTROL_SPH, field descriptions). An unlisted value is rejected or "
                    "falls back to some other behaviour without notice.",
             .fix = "Pick one of the documented values; the message lists them.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        11       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK008 missing-required
    {.code = "DK008",
     .name = "missing-required",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "schema",
     .summary = "a field without a default left blank (error), or IDIM blank or 0 (warning: it "
                "has no default)",
     .doc = {.what = "Reports a field that has no default but was left blank, such as the density "
                     "RO of a material (error). IDIM of *CONTROL_SPH blank or 0 is reported as a "
                     "warning: it has no default, but old pre-processors wrote 0 there.",
             .why = "A field without a default has nothing to fall back on, so the solver stops "
                    "or works with zero; a material without density has no mass (*MAT_NULL, RO; "
                    "*CONTROL_SPH, IDIM has no default). What LS-DYNA does with IDIM 0 is not "
                    "documented, so the dimension of the problem should be stated.",
             .fix = "Fill in the field; for IDIM write 3, 2 or -2.",
             .before = R"deck(*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1             -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck",
             .after = R"deck(*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1    1.0e-9   -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck"}},

    // DK009 too-many-cards
    {.code = "DK009",
     .name = "too-many-cards",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "schema",
     .summary = "more data cards than the keyword takes",
     .doc = {.what = "Reports data lines beyond the last card a keyword takes, e.g. a fourth card "
                     "under *CONTROL_SPH, which has at most three.",
             .why = "Extra cards are not read as part of the keyword; they usually mean a keyword "
                    "line is missing or misspelt above them, so the cards meant for that keyword "
                    "are silently lost (*CONTROL_SPH: cards 1-3, cards 2 and 3 optional).",
             .fix = "Restore the missing keyword line, or delete the surplus card.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0         0      0.01
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0         0      0.01
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // DK010 include-not-found
    {.code = "DK010",
     .name = "include-not-found",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "*INCLUDE target missing after the search path rules",
     .doc = {.what = "Reports an *INCLUDE (or *INCLUDE_TRANSFORM) file that cannot be found. "
                     "sphdeck looks in the including file's folder, then the main deck's folder, "
                     "then each *INCLUDE_PATH and *INCLUDE_PATH_RELATIVE entry, and the message "
                     "lists where it looked.",
             .why = "The solver stops when an include is missing, and everything the file "
                    "defines, often the whole mesh, is absent from the model; sphdeck's other "
                    "checks then see an incomplete deck (*INCLUDE; *INCLUDE_PATH).",
             .fix = "Correct the file name, or add the folder that holds it with *INCLUDE_PATH.",
             .before = R"deck(*INCLUDE
$# filename
mesh/particle.k
)deck",
             .after = R"deck(*INCLUDE
$# filename
mesh/particles.k
)deck"}},

    // DK011 include-cycle
    {.code = "DK011",
     .name = "include-cycle",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a file includes itself, directly or through other files",
     .doc = {.what = "Reports an include chain that returns to a file already being read, e.g. "
                     "`model.k` including `model.k`, or `a.k` including `b.k` which includes "
                     "`a.k`. The message shows the chain.",
             .why = "Reading such a deck never ends: the solver either stops or recurses until it "
                    "runs out of memory (*INCLUDE). The cause is usually a master deck's include "
                    "list pasted into one of its includes.",
             .fix = "Remove the *INCLUDE that closes the loop.",
             .before = R"deck($ file: model.k
*INCLUDE
$# filename
model.k
*INCLUDE
$# filename
particles.k
)deck",
             .after = R"deck($ file: model.k
*INCLUDE
$# filename
particles.k
)deck"}},

    // DK012 undefined-parameter
    {.code = "DK012",
     .name = "undefined-parameter",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "&name used with no *PARAMETER definition in scope",
     .doc = {.what = "Reports a reference `&name` (or `-&name`) for which no *PARAMETER is "
                     "visible: neither a global definition read earlier nor a *PARAMETER_LOCAL of "
                     "this file or the files that include it. In OpenRadioss decks: a cell `[name]` "
                     "or `&name` with no /PARAMETER/GLOBAL/INTEGER or REAL definition before it.",
             .why = "The solver cannot substitute the value and stops at input; a parameter must "
                    "be defined before it is referenced (*PARAMETER). sphdeck cannot check the "
                    "field either.",
             .fix = "Define the parameter, or correct the spelling of the reference.",
             .before = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.002
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
    &t_end
)deck",
             .after = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.002
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     &tend
)deck"}},

    // DK013 parameter-type
    {.code = "DK013",
     .name = "parameter-type",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "an R, I or C parameter used in a field of another type",
     .doc = {.what = "Reports a parameter used in a field of another type: a real (R) parameter "
                     "in an integer field, an integer in a character field, and so on. In "
                     "OpenRadioss decks: a /PARAMETER/GLOBAL/REAL value in an integer cell.",
             .why = "The first letter of a *PARAMETER name (R, I or C) fixes its type, and a "
                    "reference must sit in a field of that type (*PARAMETER, PRMR). A real "
                    "substituted into an integer field is rejected or truncated.",
             .fix = "Define the parameter with the type of the fields that use it, e.g. `I form` "
                    "for FORM.",
             .before = R"deck(*PARAMETER
$#   prmr1      val1
R form             1
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150     &form       0.0     1e+15
)deck",
             .after = R"deck(*PARAMETER
$#   prmr1      val1
I form             1
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150     &form       0.0     1e+15
)deck"}},

    // DK014 duplicate-parameter
    {.code = "DK014",
     .name = "duplicate-parameter",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a parameter defined twice, reported as *PARAMETER_DUPLICATION DFLAG says (1 "
                "warning, 3 error, ...)",
     .doc = {.what = "Reports a second definition of a parameter name. The severity follows DFLAG "
                     "of *PARAMETER_DUPLICATION: 1 (the default) and 2 give a warning, 3 an "
                     "error, 4 and 5 nothing, since the deck asked for silence. In OpenRadioss "
                     "decks: a /PARAMETER name defined twice (the first definition is kept).",
             .why = "By default LS-DYNA keeps the first definition and ignores the new one with a "
                    "warning; DFLAG 2 takes the new value, 3 stops, 4 and 5 accept or ignore it "
                    "silently (*PARAMETER_DUPLICATION). An include meant to override a value "
                    "therefore often has no effect.",
             .fix = "Keep one definition, or state the intended behaviour with "
                    "*PARAMETER_DUPLICATION.",
             .before = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.002
R tend         0.005
)deck",
             .after = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.005
)deck"}},

    // DK015 bad-expression
    {.code = "DK015",
     .name = "bad-expression",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a *PARAMETER_EXPRESSION that does not parse or cannot be evaluated",
     .doc = {.what = "Reports a *PARAMETER_EXPRESSION whose expression does not parse (unbalanced "
                     "parentheses, missing operand, unknown function) or cannot be evaluated "
                     "(division by zero, undefined name, square root of a negative number).",
             .why = "The parameter gets no value: the solver stops, and every field that uses the "
                    "parameter fails with it (*PARAMETER_EXPRESSION).",
             .fix = "Correct the expression; sphdeck points at the first character it could not "
                    "use.",
             .before = R"deck(*PARAMETER_EXPRESSION
$#    prmr                                                            expression
R dt      0.3*&h/(&c0
)deck",
             .after = R"deck(*PARAMETER_EXPRESSION
$#    prmr                                                            expression
R dt      0.3*&h/&c0
)deck"}},

    // DK016 tab-in-fixed-field
    {.code = "DK016",
     .name = "tab-in-fixed-field",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a tab inside a fixed-format data line",
     .doc = {.what = "Reports a tab character in a fixed-format data line.",
             .why = "Fixed fields are counted in characters: a tab is one character to the solver "
                    "but displays as up to eight columns, so values that look aligned in an "
                    "editor fall into other fields (LS-DYNA manual, general card format: "
                    "10-column fields).",
             .fix = "Replace tabs by spaces so that each value lies inside its columns (most "
                    "editors can expand tabs), or separate the values with commas.",
             .before = "*CONTROL_SPH\n"
                       "$#    ncbs     boxid        dt      idim    memory      form     start      maxv\n"
                       "1\t0\t1e+20\t3\t150\t1\t0.0\t1e+15\n",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK017 data-after-end
    {.code = "DK017",
     .name = "data-after-end",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "reader",
     .summary = "non-blank lines after *END",
     .doc = {.what = "Reports non-blank, non-comment lines after *END.",
             .why = "Reading stops at *END, so whatever follows is not part of the model; a "
                    "keyword appended by a script after *END is never seen by the solver (*END).",
             .fix = "Move the keywords before *END, or delete them.",
             .before = R"deck(*KEYWORD
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
*END
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     0.002         0       0.0       0.0    1.0e+8         0
)deck",
             .after = R"deck(*KEYWORD
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     0.002         0       0.0       0.0    1.0e+8         0
*END
)deck"}},

    // DK018 duplicate-control
    {.code = "DK018",
     .name = "duplicate-control",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "schema",
     .summary = "a *CONTROL_ keyword that may appear once appears twice",
     .doc = {.what = "Reports a second occurrence of a *CONTROL_ keyword that sets model-wide "
                     "options once, such as *CONTROL_SPH, *CONTROL_TERMINATION or "
                     "*CONTROL_TIMESTEP, including copies in different include files. Both "
                     "locations are shown.",
             .why = "A control keyword holds one set of global options; with two copies only one "
                    "takes effect, and which one depends on the reading order, so part of the "
                    "intended settings is lost without notice (*CONTROL_SPH and the other "
                    "*CONTROL keywords define model-wide settings).",
             .fix = "Merge the two blocks into one and delete the other.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        15       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        15       0.0     1e+15
)deck"}},

    // DK019 include-format-ignored
    {.code = "DK019",
     .name = "include-format-ignored",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "long= or i10= on the *KEYWORD line of an included file, which LS-DYNA ignores",
     .doc = {.what = "Reports `long=` or `i10=` on the *KEYWORD line of a file that is read "
                     "through *INCLUDE.",
             .why = "An included file inherits the format of the file that includes it; LS-DYNA "
                    "ignores format options on an include's own *KEYWORD line, and only a suffix "
                    "on the *INCLUDE line switches the format: `+` long, `%` I10, `-` standard "
                    "(Oasys PRIMER manual, mixing small, I10 and large format files). The include "
                    "is otherwise read with the wrong column widths.",
             .fix = "Remove the option from the included file and put the suffix on the *INCLUDE "
                    "line instead.",
             .before = R"deck($ file: main.k
*KEYWORD
*INCLUDE
$# filename
mesh_long.k
$ file: mesh_long.k
*KEYWORD long=y
)deck",
             .after = R"deck($ file: main.k
*KEYWORD
*INCLUDE +
$# filename
mesh_long.k
$ file: mesh_long.k
*KEYWORD
)deck"}},

    // DK020 keyword-not-in-column-1
    {.code = "DK020",
     .name = "keyword-not-in-column-1",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "blanks before the * of a keyword line",
     .doc = {.what = "Reports a keyword line whose `*` is preceded by blanks. sphdeck reads it as "
                     "a keyword.",
             .why = "A keyword line is recognised by `*` in column 1 (LS-DYNA manual, general "
                    "card format). Some readers accept leading blanks, others read the line as a "
                    "data card of the previous keyword, so the keyword and its cards may vanish.",
             .fix = "Start the keyword line in column 1.",
             .before = R"deck(  *SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // DK021 keyword-case
    {.code = "DK021",
     .name = "keyword-case",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a keyword name written in lower or mixed case",
     .doc = {.what = "Reports a keyword name or option written in lower or mixed case, such as "
                     "`*control_sph`.",
             .why = "LS-DYNA-style readers accept keywords in any case, but not every tool that "
                    "reads a deck does: OpenRadioss's LS-DYNA reader, for one, looks keyword "
                    "names up exactly (LS-DYNA keyword names and options). Upper case is the "
                    "portable spelling.",
             .fix = "Write the keyword name in upper case.",
             .before = R"deck(*control_sph
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK022 encrypted-block
    {.code = "DK022",
     .name = "encrypted-block",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "reader",
     .summary = "an encrypted block: its content is skipped, not checked",
     .doc = {.what = "Reports a PGP-encrypted block (`-----BEGIN PGP MESSAGE-----` to `-----END "
                     "PGP MESSAGE-----`). sphdeck keeps it as opaque text and does not report its "
                     "lines as syntax errors.",
             .why = "Suppliers ship encrypted material and part data; sphdeck cannot read it, so "
                    "anything defined inside is unknown to the other rules, which may then report "
                    "references to it as undefined or stay silent where they would have fired "
                    "(encrypted input; pydyna and qd-cae also keep such blocks unread).",
             .fix = "Nothing to change in the deck. Expect REF findings for ids defined inside "
                    "the block, or lint the unencrypted deck; a suppression comment records that "
                    "the block was reviewed.",
             .before = R"deck(*KEYWORD
$# supplier material data
-----BEGIN PGP MESSAGE-----
hQEMA8xY2n0Qb9gXAQf/Zk1vQ3RyYWN0ZWQgbWF0ZXJpYWwgZGF0YQ==
-----END PGP MESSAGE-----
)deck",
             .after = R"deck(*KEYWORD
$# supplier material data
$ sphdeck: disable=DK022 -- supplier material, reviewed with the vendor
-----BEGIN PGP MESSAGE-----
hQEMA8xY2n0Qb9gXAQf/Zk1vQ3RyYWN0ZWQgbWF0ZXJpYWwgZGF0YQ==
-----END PGP MESSAGE-----
)deck"}},

    // DK023 nend-wide-column
    {.code = "DK023",
     .name = "nend-wide-column",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "*ELEMENT_SPH NEND written in columns 41-42 (sources disagree on its width)",
     .doc = {.what = "Reports an *ELEMENT_SPH card whose NEND field uses columns 41-42, i.e. is "
                     "written 10 wide (33-42) instead of 8 wide (33-40). sphdeck reads columns "
                     "33-42.",
             .why = "Sources disagree on the width of NEND: the manual's format for the card, "
                    "2I8, E16, I8, ends it at column 40, while pydyna and LS-PrePost 4.10.5 write "
                    "it 10 wide (*ELEMENT_SPH; Oasys PRIMER format tables). A reader using 8 "
                    "columns sees only the first eight characters: `       120` becomes 1, and "
                    "the generated particle range is wrong.",
             .fix = "Right-align NEND so that it ends in column 40.",
             .before = R"deck(*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9       120
)deck",
             .after = R"deck(*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9     120
)deck"}},

    // DK024 parameter-case
    {.code = "DK024",
     .name = "parameter-case",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a parameter reference matches its definition only ignoring case, or two "
                "definitions differ only by case",
     .doc = {.what = "Reports a reference that matches a *PARAMETER only when case is ignored "
                     "(`&TEND` for `R tend`), and two definitions whose names differ only by "
                     "case. sphdeck resolves names case-insensitively.",
             .why = "Sources conflict: pydyna matches parameter names regardless of case, "
                    "following LS-DYNA, while Ansys documents LS-DYNA parameters as case "
                    "sensitive (*PARAMETER; Ansys Mechanical help on LS-DYNA parameters). A deck "
                    "that depends on either behaviour may read different values with different "
                    "tools or versions.",
             .fix = "Spell every reference exactly as its definition, and give distinct "
                    "parameters distinct names.",
             .before = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.002
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     &TEND
)deck",
             .after = R"deck(*PARAMETER
$#   prmr1      val1
R tend         0.002
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     &tend
)deck"}},

    // DK025 include-path-long
    {.code = "DK025",
     .name = "include-path-long",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "an include file name longer than 236 characters",
     .doc = {.what = "Reports an include file name longer than 236 characters once its "
                     "continuation lines (lines ending in ` +`) are joined.",
             .why = "LS-DYNA takes at most 236 characters for an include file name, written on up "
                    "to three lines continued with ` +` (*INCLUDE, Remark 2, as implemented by "
                    "pydyna and dynareadout). A longer name is cut, and the file is then not "
                    "found or, worse, another file is read.",
             .fix = "Shorten the name: give the path relative to the including file's folder, "
                    "which is searched first, or list the folder once in *INCLUDE_PATH and "
                    "include the file by its short name.",
             .before = R"deck($ file: main.k, in the run_017_... folder that holds mesh/
*INCLUDE
$# filename
/net/cae-fileserver-02/projects/aerospace/bird_strike_certification_2024_eu/ +
leading_edge_slat_inboard_section_b/campaign_q3_revised_material_data_v4_a/ +
run_017_sph_bird_1p8kg_180mps_30deg_incidence_coarse_particles_v2_final/ +
mesh/particles.k
)deck",
             .after = R"deck($ file: main.k, in the run_017_... folder that holds mesh/
*INCLUDE
$# filename
mesh/particles.k
)deck"}},

    // DK026 unused-suppression
    {.code = "DK026",
     .name = "unused-suppression",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a \"$ sphdeck: disable=\" comment that silenced nothing",
     .doc = {.what = "Reports a `$ sphdeck: disable=...` comment (or `disable-next-line`, "
                     "`disable-file`) that silenced no finding in this run, naming the codes that "
                     "were never needed.",
             .why = "A stale suppression outlives the problem it was written for and hides the "
                    "next real finding of the same rule in that place; linters such as ruff "
                    "(RUF100) and ESLint report them for the same reason (sphdeck suppression "
                    "comments).",
             .fix = "Delete the comment, or the codes in it that no longer match anything.",
             .before = R"deck($ sphdeck: disable=SPH032 -- form 2 kept for comparison
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // DK027 data-before-keyword
    {.code = "DK027",
     .name = "data-before-keyword",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "non-blank data lines before the first keyword line are ignored",
     .doc = {.what = "Reports the first non-blank line of a file that is neither a comment (`$` in "
                     "column 1) nor a keyword line and comes before the file's first keyword: a "
                     "data line that belongs to no keyword. It is reported once per file.",
             .why = "A data line holds a card of the keyword above it; with no keyword above it, "
                    "nothing reads it and its values are lost. pydyna refuses such lines and what "
                    "LS-DYNA does with them is not documented (LS-DYNA format notes, *KEYWORD). "
                    "Usually it is a note that lost its `$`, or a card whose keyword line was "
                    "deleted or cut off by an editor.",
             .fix = "Make the line a comment by putting `$` in column 1, or restore the keyword "
                    "line it belongs to.",
             .before = R"deck(units: ton, mm, s
*KEYWORD
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     0.002
)deck",
             .after = R"deck($ units: ton, mm, s
*KEYWORD
*CONTROL_TERMINATION
$#  endtim    endcyc     dtmin    endeng    endmas     nosol
     0.002
)deck"}},

    // DK028 bad-suppression
    {.code = "DK028",
     .name = "bad-suppression",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reader",
     .summary = "a \"$ sphdeck:\" comment that cannot be understood: unknown action, rule or syntax",
     .doc = {.what = "Reports a comment that starts like a suppression (`$ sphdeck:`) but cannot be "
                     "read: an action other than `disable`, `disable-next-line` or `disable-file`, "
                     "a missing `=` or code list, or a code or rule name that does not exist. "
                     "Such a comment silences nothing.",
             .why = "A misspelt suppression looks as if it worked when reading the deck, while the "
                    "findings it was meant to silence keep appearing or, worse, someone silences "
                    "them again elsewhere; clang-tidy reports malformed NOLINT comments for the "
                    "same reason (sphdeck suppression comments).",
             .fix = "Write `$ sphdeck: disable=CODE[,CODE...] -- reason` (or `disable-next-line=`, "
                    "`disable-file=`) with codes or names that `sphdeck rules` lists.",
             .before = R"deck($ sphdeck: disabel=SPH032 -- form 2 kept for comparison
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         2       0.0     1e+15
)deck",
             .after = R"deck($ sphdeck: disable=SPH032 -- form 2 kept for comparison
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         2       0.0     1e+15
)deck"}},
};

}  // namespace

std::span<const RuleInfo> dk_rule_rows() { return kDkRules; }

}  // namespace sphdeck::lint::detail
