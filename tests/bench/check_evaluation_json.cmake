# Runs `evaluation_benchmark --quick --json JSON` and checks that the JSON carries the bicubic
# grid's figures as positive numbers (no timing threshold: the machine may be busy).
execute_process(COMMAND ${BENCHMARK} --quick --json ${JSON} RESULT_VARIABLE status
                OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "evaluation_benchmark --quick failed (${status}):\n${output}\n${errors}")
endif()
file(READ ${JSON} json)
foreach(key occt_ns_per_vertex_normals best_ns_per_vertex_normals)
    string(JSON value ERROR_VARIABLE problem GET "${json}" ${key})
    if(problem)
        message(FATAL_ERROR "${key}: ${problem}")
    endif()
    if(NOT value GREATER 0)
        message(FATAL_ERROR "${key} is ${value}, not a positive number")
    endif()
    message(STATUS "${key} = ${value}")
endforeach()
