# The real recordings in shared/data/real hold no shelf of the models (rooms, furniture, people
# walking past): `shelfdock eval-real` on both bags must report 0 scans with a detection on each
# of the 5 LaserScan topics. Run with cmake -DSHELFDOCK=<binary> -DBAGS="<bag>;<bag>" -P.
execute_process(COMMAND ${SHELFDOCK} eval-real --bag ${BAGS}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "shelfdock eval-real: exit ${code}\n${out}\n${err}")
endif()
string(REGEX MATCHALL "\"scans_with_detection\": [0-9]+" counts "${out}")
list(LENGTH counts topics)
if(NOT topics EQUAL 5)
  message(FATAL_ERROR "expected 5 topics in eval-real's report, found ${topics}\n${out}")
endif()
foreach(c IN LISTS counts)
  if(NOT c MATCHES ": 0$")
    message(FATAL_ERROR "a shelf was detected in real scans that hold none (${c})\n${out}")
  endif()
endforeach()
