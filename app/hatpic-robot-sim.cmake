# hatpic-robot-sim: a simulated robot at the other end of the bridge (robot.md,
# docs/teleop.md). Included from app/CMakeLists.txt.
add_executable(hatpic-robot-sim
  hatpic-robot-sim/main.cpp
  hatpic-robot-sim/robotsimoptions.cpp hatpic-robot-sim/robotsimoptions.h)
target_link_libraries(hatpic-robot-sim PRIVATE hatpic::robotsim hatpic_appcommon
                      hatpic::build_settings)
install(TARGETS hatpic-robot-sim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
