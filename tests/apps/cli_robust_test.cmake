# Command-line contracts of issue 10: --version, one "(command line)" error style for poses,
# seeds and counts, and `detect --scan -` streaming JSON Lines from standard input.
set(DATA ${SOURCE_DIR}/tests/data)
set(MODELS ${SOURCE_DIR}/config/models.yaml)
set(SCENARIO ${SOURCE_DIR}/config/scenarios/paper_docking.yaml)
include(${CMAKE_CURRENT_LIST_DIR}/../cli_expect.cmake)

expect_shelfdock(0 "^shelfdock [0-9]+\\.[0-9]+\\.[0-9]+" --version)
expect_shelfdock(2 "error: \\(command line\\): a subcommand is required")

# Negative seeds and counts are refused, not wrapped around.
expect_shelfdock(2 "error: \\(command line\\): --seed: must be a whole number >= 0, got '-1'"
                 simulate --scenario ${SCENARIO} --pose 0,0,0 --seed -1 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "error: \\(command line\\): --count: must be >= 1" simulate
                 --scenario ${SCENARIO} --pose 0,0,0 --count -3 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "error: \\(command line\\): --seed: must be a whole number >= 0" dock
                 --scenario ${SCENARIO} --models ${MODELS} --seed -1)
expect_shelfdock(2 "error: \\(command line\\): --seed0: must be a whole number >= 0" eval-docking --scenario ${SCENARIO}
                 --models ${MODELS} --seed0 -5)
expect_shelfdock(2 "error: \\(command line\\): --runs: must be >= 1" eval-docking
                 --scenario ${SCENARIO} --models ${MODELS} --runs -2)

# One pose parser: the same message for every X,Y,YAW option.
foreach(bad "1,2" "1,2,3,4" "1,2,x" "1,2,3," "1,,3" "1,2,nan" "1,2,1e999")
  expect_shelfdock(2 "error: \\(command line\\): --preset: expected X,Y,YAW \\(m, m, rad\\), got '${bad}'"
                   detect --models ${MODELS} --scan ${DATA}/example_scan.json --preset ${bad})
endforeach()
expect_shelfdock(2 "error: \\(command line\\): --pose: expected X,Y,YAW \\(m, m, rad\\)" simulate
                 --scenario ${SCENARIO} --pose 0,0 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "error: \\(command line\\): --offset: expected X,Y,YAW \\(m, m, rad\\)" marker
                 --render ${WORK_DIR}/x.pgm --camera ${SOURCE_DIR}/config/camera.yaml --offset 1,2)

# Streaming: good line, garbage, good line -> a detection, an error naming line 2, the same
# detection again; exit 2 at the end because a line was bad.
file(READ ${DATA}/example_scan.json scan)
string(STRIP "${scan}" scan)
file(WRITE ${WORK_DIR}/stream_in.jsonl "${scan}\n{\"angle_min\": oops\n${scan}\n")
execute_process(COMMAND ${SHELFDOCK} detect --models ${MODELS} --scan -
                INPUT_FILE ${WORK_DIR}/stream_in.jsonl
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "detect --scan -: exit ${code}, expected 2\n${out}\n${err}")
endif()
string(REGEX REPLACE "\n$" "" out "${out}")
string(REPLACE "\n" ";" lines "${out}")
list(LENGTH lines n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "detect --scan -: ${n} output lines, expected 3\n${out}")
endif()
list(GET lines 0 first)
list(GET lines 1 second)
list(GET lines 2 third)
string(JSON detections LENGTH "${first}" detections)
if(detections LESS 1 OR NOT first STREQUAL third)
  message(FATAL_ERROR "detect --scan -: good lines differ or found nothing\n${out}")
endif()
string(JSON bad_line GET "${second}" line)
string(JSON bad_error GET "${second}" error)
if(NOT bad_line EQUAL 2 OR NOT bad_error MATCHES "\\(stdin\\): line 2: malformed JSON")
  message(FATAL_ERROR "detect --scan -: bad line reported as ${second}")
endif()
# The streamed result of a scan is the file result of the same scan.
execute_process(COMMAND ${SHELFDOCK} detect --models ${MODELS} --scan ${DATA}/example_scan.json
                RESULT_VARIABLE code OUTPUT_VARIABLE file_out)
string(STRIP "${file_out}" file_out)
if(NOT code EQUAL 0 OR NOT file_out STREQUAL first)
  message(FATAL_ERROR "detect: file and stream results differ\n${file_out}\n${first}")
endif()
