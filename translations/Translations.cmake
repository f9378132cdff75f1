# The German and Malay translations (translations/README.md). Included from app/gui/CMakeLists.txt: the .qm files
# are built from translations/palpate_<lang>.ts by lrelease and embedded in palpate_gui as
# :/i18n/palpate_<lang>.qm (app/gui/FirstRun.cpp loads them).
#
# After changing user-visible strings in app/gui/, widgets/, results/ or report/:
#   cmake --build build/release --target update_translations
# runs lupdate over app/gui, widgets, results, report and the engine's field tables and rewrites translations/*.ts (new strings come in as
# unfinished, removed ones are dropped); translate the unfinished entries (Qt Linguist, or by
# hand), and the translations_complete test passes again.
find_package(Qt6 REQUIRED COMPONENTS LinguistTools)

set(PALPATE_TS_FILES
  "${PROJECT_SOURCE_DIR}/translations/palpate_de.ts"
  "${PROJECT_SOURCE_DIR}/translations/palpate_ms.ts")
file(GLOB PALPATE_TR_SOURCES CONFIGURE_DEPENDS
  "${PROJECT_SOURCE_DIR}/app/gui/*.cpp" "${PROJECT_SOURCE_DIR}/app/gui/*.h"
  "${PROJECT_SOURCE_DIR}/widgets/*.cpp" "${PROJECT_SOURCE_DIR}/widgets/*.h"
  "${PROJECT_SOURCE_DIR}/results/*.cpp" "${PROJECT_SOURCE_DIR}/results/*.h"
  "${PROJECT_SOURCE_DIR}/report/*.cpp" "${PROJECT_SOURCE_DIR}/report/*.h")
# The engine's parameter tables and exercise kinds hold the labels and tooltips the panels show,
# marked with PALPATE_TRANSLATE_NOOP (base/params/FieldTable.h), which lupdate reads as
# QT_TRANSLATE_NOOP; some are in headers (the kinds' shared numbers).
file(GLOB_RECURSE PALPATE_TR_ENGINE_SOURCES CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/engine/*.cpp"
  "${PROJECT_SOURCE_DIR}/engine/*.h")
list(APPEND PALPATE_TR_SOURCES ${PALPATE_TR_ENGINE_SOURCES})

qt_add_translations(palpate_gui
  TS_FILES ${PALPATE_TS_FILES}
  SOURCES ${PALPATE_TR_SOURCES}
  INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}"
  LUPDATE_OPTIONS -no-obsolete -locations none -tr-function-alias QT_TRANSLATE_NOOP+=PALPATE_TRANSLATE_NOOP,QT_TRANSLATE_N_NOOP+=PALPATE_TRANSLATE_N_NOOP
  RESOURCE_PREFIX "/i18n")
