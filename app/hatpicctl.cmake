# hatpicctl: the command-line tool (docs/cli.md). Included from app/CMakeLists.txt.
add_executable(hatpicctl
  hatpicctl/main.cpp
  hatpicctl/subcommand.cpp hatpicctl/subcommand.h
  hatpicctl/subcommands.h
  hatpicctl/console.cpp hatpicctl/console.h
  hatpicctl/deviceoptions.cpp hatpicctl/deviceoptions.h
  hatpicctl/devicerunner.cpp hatpicctl/devicerunner.h
  hatpicctl/devicesubcommand.cpp hatpicctl/devicesubcommand.h
  hatpicctl/paramtext.cpp hatpicctl/paramtext.h
  hatpicctl/profileinput.cpp hatpicctl/profileinput.h
  hatpicctl/curvetable.cpp hatpicctl/curvetable.h
  hatpicctl/portssubcommand.cpp
  hatpicctl/infosubcommand.cpp
  hatpicctl/getsubcommand.cpp
  hatpicctl/setsubcommand.cpp
  hatpicctl/zerosubcommand.cpp
  hatpicctl/savesubcommand.cpp
  hatpicctl/streamsubcommand.cpp
  hatpicctl/curvesubcommand.cpp
  hatpicctl/simulatesubcommand.cpp
  hatpicctl/validatesubcommand.cpp
  hatpicctl/experimentsubcommand.cpp
  hatpicctl/experimenttext.cpp hatpicctl/experimenttext.h
  hatpicctl/vibratesubcommand.cpp
  hatpicctl/teleopmapsubcommand.cpp
  hatpicctl/rasterimage.cpp hatpicctl/rasterimage.h)
target_link_libraries(hatpicctl PRIVATE hatpic::core hatpic_appcommon hatpic::build_settings)
target_compile_definitions(hatpicctl PRIVATE HATPIC_VERSION="${PROJECT_VERSION}")
if(HATPIC_BUILD_UI) # teleop-map --png: the chart's SVG drawn on Qt's offscreen platform
  target_link_libraries(hatpicctl PRIVATE Qt6::Gui Qt6::Svg)
  target_compile_definitions(hatpicctl PRIVATE HATPIC_HATPICCTL_PNG)
endif()
set_target_properties(hatpicctl PROPERTIES AUTOMOC ON)
install(TARGETS hatpicctl RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
