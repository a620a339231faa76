# hatpic-sim: a simulated HATPIC joystick on a pseudo-terminal.
add_executable(hatpic-sim hatpic-sim/main.cpp)
target_link_libraries(hatpic-sim PRIVATE hatpic::core hatpic_appcommon hatpic::build_settings)
install(TARGETS hatpic-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
