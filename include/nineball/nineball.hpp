#pragma once

/// Every public header of the simulation core (link nineball::core): scenes and their results,
/// the engines, the games and their rules, a match, the computer player, fitting recorded shots.
/// The JSON contracts of the command line (nineball/json.hpp) are nineball::io's, apart.
#include "nineball/ball.hpp"
#include "nineball/cancel.hpp"
#include "nineball/colours.hpp"
#include "nineball/engine.hpp"
#include "nineball/event.hpp"
#include "nineball/fit.hpp"
#include "nineball/games.hpp"
#include "nineball/match.hpp"
#include "nineball/motion.hpp"
#include "nineball/params.hpp"
#include "nineball/planner.hpp"
#include "nineball/pocket_id.hpp"
#include "nineball/random.hpp"
#include "nineball/rules.hpp"
#include "nineball/scenes.hpp"
#include "nineball/seat.hpp"
#include "nineball/shot.hpp"
#include "nineball/sim.hpp"
#include "nineball/state_hash.hpp"
#include "nineball/table.hpp"
#include "nineball/table_markings.hpp"
#include "nineball/trace.hpp"
#include "nineball/vec2.hpp"
#include "nineball/vec3.hpp"
