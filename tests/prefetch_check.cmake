# Fails unless the built library holds the prefetches its lookups and inserts ask for. GCC once
# dropped every one of them without a word (lib/src/prefetch.hpp says how), and nothing else
# would notice: answers stay the same, only slower. Run with -DOBJDUMP=... -DLIBRARY=...
execute_process(COMMAND "${OBJDUMP}" -d --no-show-raw-insn "${LIBRARY}"
                OUTPUT_VARIABLE disassembly RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "objdump could not read ${LIBRARY}")
endif()
string(REGEX MATCHALL "[ \t]prefetch[a-z0-9]*[ \t]" prefetches "${disassembly}")
list(LENGTH prefetches count)
# A lookup's plan loads three lines for each dynamic edge of either side (six instructions, one
# loop for each side), an insert five for the next edge's samples besides that edge's name and
# three lines of the following edge's record (nine).
set(fewest 10)
if(count LESS fewest)
  message(FATAL_ERROR "${LIBRARY} holds ${count} prefetch instructions, fewer than ${fewest}: "
                      "the compiler dropped some (see lib/src/prefetch.hpp)")
endif()
message(STATUS "${LIBRARY} holds ${count} prefetch instructions")
