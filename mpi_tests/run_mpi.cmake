# Runs the MPI host harness under mpirun and judges the run (called by CTest, see
# CMakeLists.txt):
#   cmake -DMPIEXEC=mpirun -DNPFLAG=-n -DNP=4 -DEXE=mpi_test_hosts -DMESSAGES=LOG|STDERR \
#         [-DPREFLAGS=...] -P run_mpi.cmake
# Passes when mpirun exits 0, rank 0 reports "ranks NP: <n> passed, 0 failed", and the library's
# messages went where they should: with MESSAGES=LOG (INTERFACIAL_LOG set; the harness itself
# reads the log) none on stderr; with MESSAGES=STDERR exactly one FRIC line (BADMU) and one
# GAPCON line (NOSUCH), both on the stderr of the last rank, the one given bad input.
foreach(v MPIEXEC NPFLAG NP EXE MESSAGES)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_mpi.cmake: -D${v}=... missing")
  endif()
endforeach()
separate_arguments(preflags UNIX_COMMAND "${PREFLAGS}")

execute_process(
  COMMAND "${MPIEXEC}" ${NPFLAG} ${NP} ${preflags} --oversubscribe --tag-output "${EXE}"
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 540)
message("${out}")
message("--- stderr ---\n${err}")

if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun exited with ${rc}")
endif()
if(NOT out MATCHES "<stdout>:ranks ${NP}: [0-9]+ passed, 0 failed")
  message(FATAL_ERROR "no 'ranks ${NP}: <n> passed, 0 failed' line from rank 0")
endif()

# One list entry per stderr line; the messages hold ';' and brackets, which CMake lists do not.
string(REPLACE ";" "," err "${err}")
string(REPLACE "[" "(" err "${err}")
string(REPLACE "]" ")" err "${err}")
string(REPLACE "\n" ";" lines "${err}")
set(n_messages 0)
set(n_fric 0)
set(n_gapcon 0)
math(EXPR last_rank "${NP} - 1")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "interfacial:")
    continue()
  endif()
  math(EXPR n_messages "${n_messages} + 1")
  if(NOT line MATCHES "^\\([0-9]+,([0-9]+)\\)<stderr>:interfacial: ")
    message(FATAL_ERROR "a library message not on a rank's stderr: ${line}")
  endif()
  if(NOT CMAKE_MATCH_1 EQUAL last_rank)
    message(FATAL_ERROR "a message from rank ${CMAKE_MATCH_1}, which had no bad input: ${line}")
  endif()
  if(line MATCHES "interfacial: FRIC: interaction 'BADMU' \\(element 9000${last_rank},"
     AND line MATCHES "PROPS\\(2\\)")
    math(EXPR n_fric "${n_fric} + 1")
  elseif(line MATCHES "interfacial: GAPCON: interaction 'NOSUCH' \\(element 9000${last_rank},")
    math(EXPR n_gapcon "${n_gapcon} + 1")
  endif()
endforeach()

if(MESSAGES STREQUAL "LOG")
  if(NOT n_messages EQUAL 0)
    message(FATAL_ERROR "INTERFACIAL_LOG is set, yet ${n_messages} messages went to stderr")
  endif()
elseif(NOT (n_messages EQUAL 2 AND n_fric EQUAL 1 AND n_gapcon EQUAL 1))
  message(FATAL_ERROR "expected one FRIC and one GAPCON message on rank ${last_rank}'s stderr, "
    "found ${n_messages} messages (${n_fric} FRIC, ${n_gapcon} GAPCON)")
endif()
message("mpirun -n ${NP}: exit 0, tally clean, messages where expected (${MESSAGES})")
