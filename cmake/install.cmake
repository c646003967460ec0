# `make install` (cmake --install, PREFIX and DESTDIR honoured) and `make package` (CPack, a Debian package):
# the binary, a man page per subcommand made from its --help (cmake/man_pages.cmake), bash and zsh
# completions, the rule pages, the editor set-ups and the shipped decks.
include(GNUInstallDirs)
# cmake --install and cpack install what is built (the Makefile's install and package targets build the
# program and its man pages first), not the whole tree with the tests.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(SPHDECK_MAN_DIR ${PROJECT_BINARY_DIR}/man)
add_custom_command(OUTPUT ${SPHDECK_MAN_DIR}/sphdeck.1
  COMMAND ${CMAKE_COMMAND} -DSPHDECK=$<TARGET_FILE:sphdeck> -DOUT_DIR=${SPHDECK_MAN_DIR}
          -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/man_pages.cmake
  DEPENDS sphdeck ${PROJECT_SOURCE_DIR}/cmake/man_pages.cmake
  COMMENT "Writing the man pages from sphdeck --help"
  VERBATIM)
add_custom_target(sphdeck_man ALL DEPENDS ${SPHDECK_MAN_DIR}/sphdeck.1)

install(TARGETS sphdeck RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${SPHDECK_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 FILES_MATCHING PATTERN "*.1")
install(FILES ${PROJECT_SOURCE_DIR}/completions/sphdeck.bash
  DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME sphdeck)
install(FILES ${PROJECT_SOURCE_DIR}/completions/_sphdeck DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/docs/rules.md
  DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/rules DESTINATION ${CMAKE_INSTALL_DOCDIR})
# The editor set-ups as in the repository (editors/README.md); VS Code's extension is its source.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/editors DESTINATION ${CMAKE_INSTALL_DATADIR}/sphdeck
  PATTERN node_modules EXCLUDE PATTERN out EXCLUDE PATTERN .gitignore EXCLUDE PATTERN .vscodeignore EXCLUDE)
# The demo decks and the verification decks (`sphdeck verify` finds them beside the installed binary).
install(DIRECTORY
  ${PROJECT_SOURCE_DIR}/decks/demo ${PROJECT_SOURCE_DIR}/decks/run ${PROJECT_SOURCE_DIR}/decks/verification
  DESTINATION ${CMAKE_INSTALL_DATADIR}/sphdeck/decks PATTERN "*.py" EXCLUDE)

# The Debian package: Debian 12's runtime libraries, named (dpkg -I shows them).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sphdeck)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "checker, formatter and previewer for LS-DYNA and OpenRadioss SPH decks")
set(CPACK_PACKAGE_DESCRIPTION "sphdeck checks LS-DYNA and OpenRadioss SPH input decks before they reach
the solver: file:line:column diagnostics with rule codes, a formatter, smoothing-length previews, a
compact reference SPH solver and a language server for editors.")
set(CPACK_PACKAGE_CONTACT "sphdeck maintainers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
string(CONCAT CPACK_DEBIAN_PACKAGE_DEPENDS "libc6 (>= 2.34), libstdc++6 (>= 12), libgcc-s1 (>= 3.0), libgomp1 (>= 12), "
  "libfmt9 (>= 9.1.0), libtomlplusplus3 (>= 3.3.0)")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "bash-completion")
include(CPack)

# The installed tree works as the build tree's binary: report, man page, completion (tests/ci/test_install.py;
# CI runs it on the .deb of `make package` too).
if(Python3_FOUND AND NOT SPHDECK_SANITIZE AND NOT SPHDECK_FUZZ)
  add_test(NAME install-tree
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/ci/test_install.py --sphdeck $<TARGET_FILE:sphdeck>
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
endif()
