# hatpic-fw-host: the firmware's device core on Linux, servo on a USB–TTL adapter.
add_executable(hatpic-fw-host hatpic-fw-host/main.cpp)
target_link_libraries(hatpic-fw-host PRIVATE hatpic::core hatpic_appcommon hatpic::build_settings)
install(TARGETS hatpic-fw-host RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
