# Runs `shelfdock marker`: renders a code at a known offset, reads it back through the same
# PGM path a real camera image takes, and checks the bad-input exits. Invoked by CTest with
# -DSHELFDOCK, -DSOURCE_DIR, -DWORK_DIR.
set(CAMERA ${SOURCE_DIR}/config/camera.yaml)

include(${CMAKE_CURRENT_LIST_DIR}/../cli_expect.cmake)
# expect_run(<exit code> <regex> <marker arguments...>)
function(expect_run expected_code must_match)
  expect_shelfdock(${expected_code} "${must_match}" marker ${ARGN})
endfunction()

# Code 12 at x = 0.02 m, y = -0.015 m, yaw = 0.1 rad: read back within 1 mm / 5 mrad.
expect_run(0 "" --render ${WORK_DIR}/marker_12.pgm --camera ${CAMERA} --offset 0.02,-0.015,0.1
           --id 12)
expect_run(0 "\"found\":true.*\"id\":12.*\"x\":0\\.0(19|20).*\"y\":-0\\.01(4|5).*\"yaw\":0\\.(09[5-9]|10[0-5])"
           --image ${WORK_DIR}/marker_12.pgm --camera ${CAMERA})
# No code in view: {"found": false}, exit 1.
expect_run(0 "" --render ${WORK_DIR}/marker_none.pgm --camera ${CAMERA} --offset 1,1,0)
expect_run(1 "\"found\":false" --image ${WORK_DIR}/marker_none.pgm --camera ${CAMERA})

# Bad input: exit 2, the message names the file or the option.
expect_run(2 "missing.pgm" --image ${WORK_DIR}/missing.pgm --camera ${CAMERA})
file(WRITE ${WORK_DIR}/marker_truncated.pgm "P5\n640 480\n255\nabc")
expect_run(2 "marker_truncated.pgm: pixels" --image ${WORK_DIR}/marker_truncated.pgm
           --camera ${CAMERA})
file(WRITE ${WORK_DIR}/marker_bad_camera.yaml "intrinsics: {fx: -1}\n")
expect_run(2 "marker_bad_camera.yaml: intrinsics.fx" --image ${WORK_DIR}/marker_12.pgm
           --camera ${WORK_DIR}/marker_bad_camera.yaml)
expect_run(2 "--offset" --render ${WORK_DIR}/x.pgm --camera ${CAMERA} --offset 1,2)
expect_run(2 "--id" --render ${WORK_DIR}/x.pgm --camera ${CAMERA} --id 587)
