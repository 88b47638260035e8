# Warnings are errors on the project's own code (not on third-party headers, which are
# included as SYSTEM by their imported targets).
function(gsph_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror -Wshadow -Wnon-virtual-dtor
                                           -Wpedantic)
endfunction()
