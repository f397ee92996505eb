# Stages one cargo build under its installed names (run by CMakeLists.txt after cargo):
#   FROM/libinterfacial.a   -> TO/STEM.a, with the WEAK symbols made weak (objcopy)
#   FROM/libinterfacial.so  -> TO/STEM.so.VERSION, links TO/STEM.so.SOVERSION and TO/STEM.so
# Only what cargo rebuilt is copied again.
foreach(v FROM TO STEM VERSION SOVERSION)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "stage.cmake: ${v} is not set")
  endif()
endforeach()
file(MAKE_DIRECTORY "${TO}")

set(a_in "${FROM}/libinterfacial.a")
set(a_out "${TO}/${STEM}.a")
if(NOT EXISTS "${a_in}")
  message(FATAL_ERROR "stage.cmake: ${a_in} is missing (did cargo build fail?)")
endif()
if("${a_in}" IS_NEWER_THAN "${a_out}")
  set(tmp "${a_out}.tmp")
  file(COPY_FILE "${a_in}" "${tmp}")
  if(OBJCOPY)
    # A host that defines one of the Abaqus entry points itself keeps its own: the archive's
    # definitions are weak, so the linker takes the host's strong one without a "multiple
    # definition" error, and still pulls the archive member for the entry points the host
    # does not define.
    set(args "")
    string(REPLACE "," ";" WEAK "${WEAK}")
    foreach(sym IN LISTS WEAK)
      list(APPEND args "--weaken-symbol=${sym}")
    endforeach()
    execute_process(COMMAND "${OBJCOPY}" ${args} "${tmp}" RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "stage.cmake: ${OBJCOPY} ${args} ${tmp} failed (${rc})")
    endif()
  endif()
  file(RENAME "${tmp}" "${a_out}")
endif()

set(so_in "${FROM}/libinterfacial.so")
set(so_out "${TO}/${STEM}.so.${VERSION}")
if(EXISTS "${so_in}")
  if("${so_in}" IS_NEWER_THAN "${so_out}")
    file(COPY_FILE "${so_in}" "${so_out}")
  endif()
  file(CREATE_LINK "${STEM}.so.${VERSION}" "${TO}/${STEM}.so.${SOVERSION}" SYMBOLIC)
  file(CREATE_LINK "${STEM}.so.${SOVERSION}" "${TO}/${STEM}.so" SYMBOLIC)
endif()
