" OpenRadioss deck: headers, comments, includes and parameters while no server colours the buffer.
if exists("b:current_syntax")
  finish
endif
syntax match openradiossComment "^[#$].*$"
syntax match openradiossInclude "^#include\>.*$"
syntax match openradiossHeader "^/[A-Za-z0-9_/]\+"
syntax match openradiossParameter "\[[A-Za-z_][A-Za-z0-9_]*\]"
highlight default link openradiossComment Comment
highlight default link openradiossInclude Include
highlight default link openradiossHeader Keyword
highlight default link openradiossParameter Identifier
let b:current_syntax = "openradioss"
