# hatpic-servo-sim: an emulated STS3032 servo on a pseudo-terminal (for hatpic-fw-host).
add_executable(hatpic-servo-sim hatpic-servo-sim/main.cpp)
target_link_libraries(hatpic-servo-sim PRIVATE hatpic::core hatpic_appcommon hatpic::build_settings)
install(TARGETS hatpic-servo-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
