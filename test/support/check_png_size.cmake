# Checks that a PNG file has the expected size, from its header (the IHDR chunk's width and
# height, big-endian at bytes 16-23):
#   cmake -DFILE=picture.png -DWIDTH=w -DHEIGHT=h -P check_png_size.cmake
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "no picture '${FILE}'")
endif()
file(READ "${FILE}" signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "'${FILE}' is not a PNG file")
endif()
file(READ "${FILE}" size OFFSET 16 LIMIT 8 HEX)
string(SUBSTRING "${size}" 0 8 w)
string(SUBSTRING "${size}" 8 8 h)
math(EXPR w "0x${w}")
math(EXPR h "0x${h}")
if(NOT w EQUAL WIDTH OR NOT h EQUAL HEIGHT)
  message(FATAL_ERROR "'${FILE}' is ${w} x ${h}, expected ${WIDTH} x ${HEIGHT}")
endif()
message(STATUS "'${FILE}': ${w} x ${h}")
