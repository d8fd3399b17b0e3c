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
# Where nothing is inlined (the fewest): a lookup's plan loads up to three lines for each dynamic
# edge (its stamps, unless it is steady, and two samples), an insert four for the edge after next
# (its oldest stamps, its newest sample, and the slot and stamp a new sample takes) besides that
# edge's name and the lines of the following edge's record (nine).
set(fewest 9)
if(count LESS fewest)
  message(FATAL_ERROR "${LIBRARY} holds ${count} prefetch instructions, fewer than ${fewest}: "
                      "the compiler dropped some (see lib/src/prefetch.hpp)")
endif()
message(STATUS "${LIBRARY} holds ${count} prefetch instructions")
