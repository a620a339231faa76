# hatpic-tuner: the tuning window. Included from app/CMakeLists.txt when HATPIC_BUILD_UI is on.
add_executable(hatpic-tuner hatpic-tuner/main.cpp hatpic-tuner/tuneroptions.cpp
                            hatpic-tuner/tuneroptions.h)
target_link_libraries(hatpic-tuner PRIVATE hatpic::ui hatpic_appcommon hatpic::build_settings)
target_compile_definitions(hatpic-tuner PRIVATE HATPIC_VERSION="${PROJECT_VERSION}")
set_target_properties(hatpic-tuner PROPERTIES AUTOMOC ON)
install(TARGETS hatpic-tuner RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/resources/hatpic-tuner.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/hatpic-tuner.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/hatpic-tuner.png
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/256x256/apps)
foreach(size 16 24 32 48 64 128)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/png/hatpic-tuner-${size}.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps
          RENAME hatpic-tuner.png)
endforeach()
