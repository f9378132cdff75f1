#pragma once

#include "engine/accuracy/HyperelasticValidation.h"

#include "engine/exercise/Exercise.h"
#include "engine/exercise/ScoreReport.h"

#include <string>
#include <vector>

namespace palpate::cli {

int meshCommand(const std::vector<std::string>& words);
int benchCommand(const std::vector<std::string>& words);
/// bench models: every deformation model's tick at the Table 1 sizes and 100k (BenchModelsCommand.cpp).
int benchModelsCommand(const std::vector<std::string>& words);
/// bench feel: what the hand feels of a slide at constant depth, every model (BenchFeelCommand.cpp).
int benchFeelCommand(const std::vector<std::string>& words);
int demoCommand(const std::vector<std::string>& words);
int loopCommand(const std::vector<std::string>& words);
int runCommand(const std::vector<std::string>& words);
int recordCommand(const std::vector<std::string>& words);
/// score: a recorded exercise session's score and breakdown (ScoreCommand.cpp, docs/scoring.md).
int scoreCommand(const std::vector<std::string>& words);
/// trainee: list, add-session, curve, staircase over the results database (TraineeCommand.cpp,
/// docs/scoring.md "Proficiency" and "Staircase").
int traineeCommand(const std::vector<std::string>& words);
/// results list|export|sync: the stored results, and copying them to the class's server.
int resultsCommand(const std::vector<std::string>& words);
/// For `score --db --trainee`: the "proficiency" object as JSON text ("" when the exercise has no
/// expert sessions), or "" with `error` (unreadable database, unknown trainee).
std::string proficiencyJsonForScore(const ScoreReport& report, const Exercise& exercise, const std::string& exercisePath,
                                    const std::string& databasePath, const std::string& traineeName,
                                    std::string& error);
int sweepCommand(const std::vector<std::string>& words);
int calibrateCommand(const std::vector<std::string>& words);
int accuracyCommand(const std::vector<std::string>& words);
/// The hyperelastic references of `accuracy` (app/cli/HyperelasticAccuracy.cpp).
int hyperelasticAccuracyCommand(HyperelasticReference reference, const std::vector<std::string>& words);
/// stability: maps of where each model fails, derived against measured (StabilityCommand.cpp, docs/stability.md).
int stabilityCommand(const std::vector<std::string>& words);
/// devices: backends compiled in and devices connected, with their URIs (DevicesCommand.cpp, docs/devices.md).
int devicesCommand(const std::vector<std::string>& words);
/// lod: mesh levels of detail and the plan of the cheapest model a scene needs (LodCommand.cpp, docs/lod.md).
int lodCommand(const std::vector<std::string>& words);

}  // namespace palpate::cli
