# Warnings every Tessera target builds with; applied per target so that
# consumers of the installed package do not inherit them.
function(tessera_set_warnings target)
    target_compile_options(${target} PRIVATE
        # Vulkan structs are initialised as {sType} and the rest zeroed, by design.
        $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor -Werror=return-type -Wno-missing-field-initializers>)
endfunction()
