# Warning flags for every fddem target (STYLE.md §12), carried by an interface target.
add_library(fddem_warnings INTERFACE)
target_compile_options(fddem_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual
    -Wold-style-cast -Wnull-dereference -Wfloat-conversion -Wdouble-promotion
    -Wimplicit-fallthrough -Wmisleading-indentation)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(fddem_warnings INTERFACE
        -Wduplicated-cond -Wduplicated-branches -Wlogical-op)
endif()
if(FDDEM_WERROR)
    target_compile_options(fddem_warnings INTERFACE -Werror)
endif()
