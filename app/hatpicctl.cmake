# hatpicctl: the command-line tool (docs/cli.md). Included from app/CMakeLists.txt.
add_executable(hatpicctl
  hatpicctl/main.cpp
  hatpicctl/command.cpp hatpicctl/command.h
  hatpicctl/commands.h
  hatpicctl/console.cpp hatpicctl/console.h
  hatpicctl/deviceoptions.cpp hatpicctl/deviceoptions.h
  hatpicctl/devicerunner.cpp hatpicctl/devicerunner.h
  hatpicctl/devicecommand.cpp hatpicctl/devicecommand.h
  hatpicctl/paramtext.cpp hatpicctl/paramtext.h
  hatpicctl/profileinput.cpp hatpicctl/profileinput.h
  hatpicctl/curvetable.cpp hatpicctl/curvetable.h
  hatpicctl/portscommand.cpp
  hatpicctl/infocommand.cpp
  hatpicctl/getcommand.cpp
  hatpicctl/setcommand.cpp
  hatpicctl/zerocommand.cpp
  hatpicctl/savecommand.cpp
  hatpicctl/streamcommand.cpp
  hatpicctl/curvecommand.cpp
  hatpicctl/simulatecommand.cpp
  hatpicctl/validatecommand.cpp
  hatpicctl/experimentcommand.cpp
  hatpicctl/experimenttext.cpp hatpicctl/experimenttext.h
  hatpicctl/vibratecommand.cpp)
target_link_libraries(hatpicctl PRIVATE hatpic::core hatpic_appcommon hatpic::build_settings)
target_compile_definitions(hatpicctl PRIVATE HATPIC_VERSION="${PROJECT_VERSION}")
set_target_properties(hatpicctl PROPERTIES AUTOMOC ON)
install(TARGETS hatpicctl RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
