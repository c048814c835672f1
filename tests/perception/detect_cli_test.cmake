# Runs `shelfdock detect` on the example scan and on bad inputs; checks exit codes and that
# errors name the file and the field. Invoked by CTest with -DSHELFDOCK, -DSOURCE_DIR, -DWORK_DIR.
set(MODELS ${SOURCE_DIR}/config/models.yaml)
set(DATA ${SOURCE_DIR}/tests/data)

include(${CMAKE_CURRENT_LIST_DIR}/../cli_expect.cmake)
# expect_run(<exit code> <regex> <detect arguments...>)
function(expect_run expected_code must_match)
  expect_shelfdock(${expected_code} "${must_match}" detect ${ARGN})
endfunction()

# The example scan holds one t1-rect-1075x883 at (2.0, 0.2, 0.1): x within 10 mm of the truth
# (1.99 or 2.00); with frames given.
expect_run(0 "\"model\":\"t1-rect-1075x883\".*\"x\":(1\\.99|2\\.00)" --models ${MODELS}
           --scan ${DATA}/example_scan.json)
expect_run(0 "\"base\":.*\"map\":" --models ${MODELS} --scan ${DATA}/example_scan.json
           --preset 2.1,0.1,0.0 --extrinsic 0.3,0,0 --robot-pose 1,2,0.5
           --params ${SOURCE_DIR}/config/detector.yaml)
# The scan's own range noise is in the stats (the example scan was simulated with 10 mm range
# noise: the estimate must read 9.0-10.9 mm; it reads 9.7).
expect_run(0 "\"stats\":{.*\"range_noise_m\":0\\.0(09|10)[0-9]*[,}]" --models ${MODELS}
           --scan ${DATA}/example_scan.json)
# The map names the model (--model): the shelf is found as that model. Named as its close twin
# (1080x856, 5 mm longer and 27 mm narrower between leg centres, within Eq. 2's tolerances) it is
# not forced into it: its legs fit the twin too badly for the confidence bound (0.26), so nothing
# is returned; nor as the 900x810 round-legged model. The example scan comes from an older
# simulator whose receiver blended every edge beam (all 5 of its large depth steps bridged by a
# mixed return): the detector takes it for a blending sensor, whose legs may look narrower
# (evidence.leg_width_blend_beams), and then the twin passes at confidence 0.36; the twin's test
# reads the scan as from a sensor that separates far echoes (tests/data/
# detector_separating_receiver.yaml).
expect_run(0 "\"bridged_steps\":5,.*\"depth_steps\":0," --models ${MODELS}
           --scan ${DATA}/example_scan.json)
expect_run(0 "\"model\":\"t1-rect-1075x883\".*\"x\":(1\\.99|2\\.00)" --models ${MODELS}
           --scan ${DATA}/example_scan.json --model t1-rect-1075x883)
expect_run(0 "\"detections\":\\[\\].*\"low_confidence\":1" --models ${MODELS}
           --scan ${DATA}/example_scan.json --model t1-rect-1080x856
           --params ${DATA}/detector_separating_receiver.yaml)
expect_run(0 "\"detections\":\\[\\]" --models ${MODELS} --scan ${DATA}/example_scan.json
           --model t1-round-900x810)
# No shelf where the preset looks (far from the shelf, ROI empty): empty list, exit 0.
expect_run(0 "\"detections\":\\[\\]" --models ${MODELS} --scan ${DATA}/example_scan.json
           --preset -3,3,0)

# Bad input: exit 2, the message names the file and the field.
expect_run(2 "missing.json" --models ${MODELS} --scan ${DATA}/missing.json)
expect_run(2 "malformed_scan.json" --models ${MODELS} --scan ${DATA}/malformed_scan.json)
expect_run(2 "nan_text_scan.json" --models ${MODELS} --scan ${DATA}/nan_text_scan.json)
expect_run(2 "--preset" --models ${MODELS} --scan ${DATA}/example_scan.json --preset 1,2)
expect_run(2 "--extrinsic" --models ${MODELS} --scan ${DATA}/example_scan.json --extrinsic a,b,c)
expect_run(2 "--robot-pose" --models ${MODELS} --scan ${DATA}/example_scan.json --robot-pose 1,2,nan)
expect_run(2 "detector_unknown_key.yaml: preprocess.clustre_gap_beams" --models ${MODELS}
           --scan ${DATA}/example_scan.json --params ${DATA}/detector_unknown_key.yaml)
expect_run(2 "detector_impossible_value.yaml: model_match.gamma_L_m" --models ${MODELS}
           --scan ${DATA}/example_scan.json --params ${DATA}/detector_impossible_value.yaml)
expect_run(2 "models.yaml: --model: no model 't1-rect-1000x800' in the file; it holds t1-round"
           --models ${MODELS} --scan ${DATA}/example_scan.json --model t1-rect-1000x800)
expect_run(2 "missing_models.yaml" --models ${DATA}/missing_models.yaml
           --scan ${DATA}/example_scan.json)
