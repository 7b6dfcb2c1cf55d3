# What the LAMMPS test scripts share (included by them):
#   lammps_launcher(out): in `out`, the command prefix that runs LAMMPS on
#     NP MPI ranks (empty for NP <= 1).  Root (as in CI) needs
#     --allow-run-as-root; --oversubscribe lets 2 ranks run where fewer
#     cores are free.
#   lammps_var_args(out): in `out`, the -var arguments of VARS, "name
#     value|name value" ('|' between the pairs, since a ';' would split the
#     argument on its way through add_test; a value with spaces in single
#     quotes).
function(lammps_launcher out)
  set(launcher "")
  if(NP AND NP GREATER 1)
    set(launcher "${MPIEXEC}" --allow-run-as-root --oversubscribe -np ${NP})
  endif()
  set(${out} "${launcher}" PARENT_SCOPE)
endfunction()
function(lammps_var_args out)
  set(args "")
  string(REPLACE "|" ";" pairs "${VARS}")
  foreach(pair IN LISTS pairs)
    separate_arguments(words UNIX_COMMAND "${pair}")
    list(APPEND args -var ${words})
  endforeach()
  set(${out} "${args}" PARENT_SCOPE)
endfunction()
