# The German and Malay translations (issue 12). Included from app/gui/CMakeLists.txt: the .qm files
# are built from translations/palpate_<lang>.ts by lrelease and embedded in palpate_gui as
# :/i18n/palpate_<lang>.qm (app/gui/FirstRun.cpp loads them).
#
# After changing user-visible strings in app/gui/, widgets/ or app/report/:
#   cmake --build build/release --target update_translations
# runs lupdate over app/gui, widgets and app/report and rewrites translations/*.ts (new strings come in as
# unfinished, removed ones are dropped); translate the unfinished entries (Qt Linguist, or by
# hand), and the translations_complete test passes again.
find_package(Qt6 REQUIRED COMPONENTS LinguistTools)

set(PALPATE_TS_FILES
  "${PROJECT_SOURCE_DIR}/translations/palpate_de.ts"
  "${PROJECT_SOURCE_DIR}/translations/palpate_ms.ts")
file(GLOB PALPATE_TR_SOURCES CONFIGURE_DEPENDS
  "${PROJECT_SOURCE_DIR}/app/gui/*.cpp" "${PROJECT_SOURCE_DIR}/app/gui/*.h"
  "${PROJECT_SOURCE_DIR}/widgets/*.cpp" "${PROJECT_SOURCE_DIR}/widgets/*.h"
  "${PROJECT_SOURCE_DIR}/app/report/*.cpp" "${PROJECT_SOURCE_DIR}/app/report/*.h")

qt_add_translations(palpate_gui
  TS_FILES ${PALPATE_TS_FILES}
  SOURCES ${PALPATE_TR_SOURCES}
  INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}"
  LUPDATE_OPTIONS -no-obsolete -locations none
  RESOURCE_PREFIX "/i18n")
