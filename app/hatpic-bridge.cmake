# hatpic-bridge: the robot bridge on ROS 2 or ROS 1 (docs/ros.md). Included from app/CMakeLists.txt.
add_executable(hatpic-bridge
  hatpic-bridge/main.cpp
  hatpic-bridge/bridgeoptions.cpp hatpic-bridge/bridgeoptions.h
  hatpic-bridge/bridgeprogram.cpp hatpic-bridge/bridgeprogram.h)
target_link_libraries(hatpic-bridge PRIVATE hatpic::bridge hatpic_appcommon hatpic::build_settings)
set_target_properties(hatpic-bridge PROPERTIES AUTOMOC ON)
install(TARGETS hatpic-bridge RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
