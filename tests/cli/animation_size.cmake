# The animated SVG of a 360-frame horse turntable is at most a quarter of
# the size of its 360 static frame SVGs (prints both figures; 15% when
# dashes were a dash array, 21% since they are pieces of the line, which
# keeps them where the static frames draw them: docs/animation.md), and its paths
# persist: at least 80% of the stroke length x frames carried by paths shown
# 30 frames or more, at most 10% of the paths shown one frame only, and
# without SMIL only the paths of frame 0 show (measured by PERSISTENCE from
# the SVG itself). Also writes the Lottie of the same animation and prints
# both sizes.
#   cmake -DCLI=... -DPERSISTENCE=... -DMESH=... -DOUT=<dir> -P animation_size.cmake
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND ${CLI} animate ${MESH} --turntable 1 --frames 360 --fps 24
    --view-dir 1,0.2,0.3 --up 0,0,1 -o ${OUT}/horse.svg --frames-dir ${OUT}/frames
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "animate failed (${rc}): ${err}")
endif()
file(SIZE ${OUT}/horse.svg animated)
file(GLOB frames ${OUT}/frames/frame_*.svg)
list(LENGTH frames count)
if(NOT count EQUAL 360)
  message(FATAL_ERROR "expected 360 static frames, found ${count}")
endif()
set(total 0)
foreach(f IN LISTS frames)
  file(SIZE ${f} s)
  math(EXPR total "${total} + ${s}")
endforeach()
math(EXPR ratio_pct "100 * ${animated} / ${total}")
message("animated SVG ${animated} bytes; 360 static SVGs ${total} bytes; ratio ${ratio_pct}%")
math(EXPR limit "${total} / 4")
if(animated GREATER limit)
  message(FATAL_ERROR "the animated SVG is more than a quarter of the static frames")
endif()
execute_process(COMMAND ${PERSISTENCE} ${OUT}/horse.svg 360 --strokes 30 0.8 --one-frame 0.1 --frame0-only
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the animated SVG's paths do not persist as they should")
endif()
# The same animation as Lottie: its size beside the SVG's (docs/lottie.md
# explains why a polyline vertex costs Lottie about three times what it
# costs SVG path data); a regression guard, not the SVG's size.
execute_process(COMMAND ${CLI} animate ${MESH} --turntable 1 --frames 360 --fps 24
    --view-dir 1,0.2,0.3 --up 0,0,1 -o ${OUT}/horse.json
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "animate -o horse.json failed (${rc}): ${err}")
endif()
file(SIZE ${OUT}/horse.json lottie)
math(EXPR lottie_pct "100 * ${lottie} / ${animated}")
message("Lottie ${lottie} bytes: ${lottie_pct}% of the animated SVG's ${animated}")
math(EXPR lottie_limit "3 * ${animated}")
if(lottie GREATER lottie_limit)
  message(FATAL_ERROR "the Lottie file is more than three times the animated SVG")
endif()
file(REMOVE_RECURSE "${OUT}/frames")
