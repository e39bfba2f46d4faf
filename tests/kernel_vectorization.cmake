# CTest script: the hot bond loops of models/state_based_kernels.cpp stay vectorized in every clone.
# Disassembles the object the library is built from and counts, per clone of each kernel, the packed
# double-precision arithmetic on the clone's vector registers: zmm for x86-64-v4 (AVX-512), ymm for
# x86-64-v3 (AVX2+FMA), xmm for the baseline (SSE2). A scalar loop has none; the force kernels also
# evaluate the exp polynomial (12 Horner steps) in vectors. Usage:
#   cmake -DOBJDUMP=<objdump> -DOBJECTS=<list of object files> -P kernel_vectorization.cmake
foreach(o IN LISTS OBJECTS)
  if(o MATCHES "state_based_kernels\\.cpp\\.o$")
    set(object "${o}")
  endif()
endforeach()
if(NOT object OR NOT EXISTS "${object}")
  message(FATAL_ERROR "no object of state_based_kernels.cpp among: ${OBJECTS}")
endif()
execute_process(COMMAND "${OBJDUMP}" -d --no-show-raw-insn -C "${object}" OUTPUT_VARIABLE asm RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} failed on ${object}")
endif()

# Split the listing into functions: "<address> <name>:" starts one.
string(REPLACE ";" "," asm "${asm}")
string(REGEX REPLACE "\n([0-9a-f]+ <)" "\n;\\1" asm "${asm}")
set(failures "")
# kernel, least packed arithmetic instructions per clone
foreach(spec "tensileOnly:16" "tensileAndHydrostatic:16" "strain:3")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 kernel)
  list(GET spec 1 least)
  foreach(clone "arch_x86_64_v4:zmm" "arch_x86_64_v3:ymm" "default:xmm")
    string(REPLACE ":" ";" clone "${clone}")
    list(GET clone 0 suffix)
    list(GET clone 1 reg)
    set(body "")
    foreach(f IN LISTS asm)
      if(f MATCHES "^[0-9a-f]+ <[^>]*::${kernel}\\([^>]*\\[clone \\.${suffix}\\]>:")
        set(body "${f}")
      endif()
    endforeach()
    if(body STREQUAL "")
      string(APPEND failures "  ${kernel} [clone .${suffix}]: not found\n")
      continue()
    endif()
    # Packed double arithmetic (add, sub, mul, fused multiply-add) with a ${reg} destination.
    string(REGEX MATCHALL "\t(v?(add|sub|mul)pd|vf[n]?m(add|sub)[0-9]+pd) [^\n]*%${reg}[0-9]+\n" hits "${body}")
    list(LENGTH hits count)
    message(STATUS "${kernel} [clone .${suffix}]: ${count} packed double operations on ${reg}")
    if(count LESS least)
      string(APPEND failures "  ${kernel} [clone .${suffix}]: ${count} packed double operations on ${reg}, expected >= ${least}\n")
    endif()
  endforeach()
endforeach()
if(NOT failures STREQUAL "")
  message(FATAL_ERROR "bond loops not vectorized in ${object}:\n${failures}"
                      "(check with -fopt-info-vec-missed; DESIGN 8)")
endif()
