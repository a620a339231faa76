# hatpic-fw-host: the firmware's device core on Linux, servo on a USB–TTL adapter.
add_executable(hatpic-fw-host hatpic-fw-host/main.cpp
  common/quitonsignal.cpp common/quitonsignal.h)
target_include_directories(hatpic-fw-host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_link_libraries(hatpic-fw-host PRIVATE hatpic::core hatpic::build_settings)
install(TARGETS hatpic-fw-host RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
