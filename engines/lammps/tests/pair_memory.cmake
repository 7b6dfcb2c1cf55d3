# The pair's memory_usage() against the arrays it allocates
# (check_pair_memory.cpp says how): engines/lammps/tests/in.pair_memory with 1 and
# NTYPES atom types, granular/spinslide and LAMMPS' pair_style granular.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DCHECK=... -DNTYPES=300 -DDIR=... -P pair_memory.cmake
foreach(var LMP PLUGIN INPUT CHECK NTYPES DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "pair_memory.cmake: pass -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
set(logs "")
foreach(style IN ITEMS spinslide stock)
  foreach(ntypes IN ITEMS 1 ${NTYPES})
    execute_process(
      COMMAND "${LMP}" -in "${INPUT}" -var plugin "${PLUGIN}" -var style ${style}
              -var ntypes ${ntypes} -log "log.${style}.${ntypes}" -screen none
      WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
    if(NOT ran EQUAL 0)
      message(FATAL_ERROR "pair_memory.cmake: LAMMPS failed (${DIR}/log.${style}.${ntypes})")
    endif()
    list(APPEND logs "log.${style}.${ntypes}")
  endforeach()
endforeach()
execute_process(COMMAND "${CHECK}" ${NTYPES} ${logs} WORKING_DIRECTORY "${DIR}"
                RESULT_VARIABLE counted)
if(NOT counted EQUAL 0)
  message(FATAL_ERROR "pair_memory.cmake: memory_usage() does not count the pair's arrays")
endif()
