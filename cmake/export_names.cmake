# roomsense_export_names(MAP OUT): the global names of a GNU ld version script (`global: a; b; local: *;`), the
# one list of what a shared library exports. Used at configure time (exports.cmake) and by the tests' -P scripts.
function(roomsense_export_names map out)
  file(READ ${map} text)
  string(REGEX REPLACE "/\\*.*\\*/" "" text "${text}")  # the comment
  string(REGEX MATCH "global:([^}]*)local:" _ "${text}")
  string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" names "${CMAKE_MATCH_1}")
  list(SORT names)
  set(${out} ${names} PARENT_SCOPE)
endfunction()
