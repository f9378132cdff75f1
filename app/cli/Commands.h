#pragma once

#include "app/cli/CommandLine.h"
#include "engine/accuracy/HyperelasticValidation.h"

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"

#include <string>
#include <vector>

namespace palpate::cli {

class CommandLine;

// Each command file defines its commands, their options and what runs them (CommandLine.h).
void defineMeshCommands(CommandLine& cli);
/// bench table1, models (BenchModelsCommand.cpp), feel (BenchFeelCommand.cpp).
void defineBenchCommands(CommandLine& cli);
void defineDemoCommand(CommandLine& cli);
void defineLoopCommand(CommandLine& cli);
void defineRunCommand(CommandLine& cli);
void defineRecordCommands(CommandLine& cli);
/// score: a recorded exercise session's score and breakdown (ScoreCommand.cpp, docs/scoring.md).
void defineScoreCommand(CommandLine& cli);
/// trainee: list, add-session, curve, staircase over the results database (TraineeCommand.cpp,
/// docs/scoring.md "Proficiency" and "Staircase").
void defineTraineeCommands(CommandLine& cli);
/// exercise bundle|import: an exercise with its mesh, preset and scripted paths as one file
/// (ExerciseCommands.cpp, docs/scoring.md "Exercise bundles").
void defineExerciseCommands(CommandLine& cli);
/// results list|export|sync|class|grant|revoke: the stored results, and copying them to the class's server.
void defineResultsCommands(CommandLine& cli);
void defineSweepCommand(CommandLine& cli);
void defineCalibrateCommand(CommandLine& cli);
/// accuracy, with the hyperelastic references of app/cli/HyperelasticAccuracy.cpp.
void defineAccuracyCommand(CommandLine& cli);
/// stability: maps of where each model fails, derived against measured (StabilityCommand.cpp, docs/stability.md).
void defineStabilityCommand(CommandLine& cli);
/// devices: backends compiled in and devices connected, with their URIs (DevicesCommand.cpp, docs/devices.md).
void defineDevicesCommand(CommandLine& cli);
/// lod: mesh levels of detail and the plan of the cheapest model a scene needs (LodCommand.cpp, docs/lod.md).
void defineLodCommands(CommandLine& cli);

/// bench models: every deformation model's tick at the Table 1 sizes and 100k (BenchModelsCommand.cpp).
int benchModelsCommand(const Given& args);
/// bench feel: what the hand feels of a slide at constant depth, every model (BenchFeelCommand.cpp).
int benchFeelCommand(const Given& args);
/// Their options (defined beside them).
void defineBenchModelsOptions(CLI::App& command);
void defineBenchFeelOptions(CLI::App& command);
/// For `score --db --trainee`: the "proficiency" object as JSON text ("" when the exercise has no
/// expert sessions), or "" with `error` (unreadable database, unknown trainee).
std::string proficiencyJsonForScore(const ScoreReport& report, const Exercise& exercise, const std::string& exercisePath,
                                    const std::string& databasePath, const std::string& traineeName,
                                    std::string& error);
/// The hyperelastic references of `accuracy` (app/cli/HyperelasticAccuracy.cpp).
int hyperelasticAccuracyCommand(HyperelasticReference reference, const Given& args);

}  // namespace palpate::cli
