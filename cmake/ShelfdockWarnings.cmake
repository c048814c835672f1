# One place for compiler warnings. CI sets SHELFDOCK_WERROR=ON so that warnings fail the build.
option(SHELFDOCK_WERROR "Treat compiler warnings as errors" OFF)

function(shelfdock_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(SHELFDOCK_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
