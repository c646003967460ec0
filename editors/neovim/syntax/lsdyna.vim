" LS-DYNA deck: keywords, comments and parameters while no server colours the buffer (sphdeck lsp's
" semantic tokens, Neovim 0.9+, colour every value over this).
if exists("b:current_syntax")
  finish
endif
syntax match lsdynaHeader "^\$#.*$"
syntax match lsdynaComment "^\$\%(#\)\@!.*$"
syntax match lsdynaKeyword "^\*[A-Za-z][A-Za-z0-9_-]*[+%-]\="
syntax match lsdynaParameter "&[A-Za-z_][A-Za-z0-9_]*"
highlight default link lsdynaHeader SpecialComment
highlight default link lsdynaComment Comment
highlight default link lsdynaKeyword Keyword
highlight default link lsdynaParameter Identifier
let b:current_syntax = "lsdyna"
