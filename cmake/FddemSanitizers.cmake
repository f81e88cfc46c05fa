# Sanitizer flags (FDDEM_SANITIZE), applied through an interface target.
add_library(fddem_sanitizers INTERFACE)
if(FDDEM_SANITIZE)
    target_compile_options(fddem_sanitizers INTERFACE
        -fsanitize=${FDDEM_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer
        -D_GLIBCXX_ASSERTIONS)
    target_link_options(fddem_sanitizers INTERFACE -fsanitize=${FDDEM_SANITIZE})
endif()
