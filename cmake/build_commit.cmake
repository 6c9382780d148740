# Writes OUT (a C++ file defining antumbra::app::build_commit()) with the source tree's
# commit, "+dirty" when tracked files differ from it, "unknown" outside a git checkout.
# Run at every build by the antumbra_build_commit target; configure_file rewrites OUT
# only when the text changes, so an unchanged commit recompiles nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY "${SRC}"
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE rc ERROR_QUIET)
if(NOT rc EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
else()
  execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY "${SRC}"
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND commit "+dirty")
  endif()
endif()
set(ANTUMBRA_BUILD_COMMIT "${commit}")
configure_file("${TEMPLATE}" "${OUT}" @ONLY)
