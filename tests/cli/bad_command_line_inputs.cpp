// Bad command lines (--set values, missing files, unwritable outputs), control bytes quoted from
// the input, and bad MovingAI maps, scenario files and `cosim mapf` options.
#include <string>
#include <vector>

#include "tests/cli/bad_input_case.h"

namespace cosim::test {

std::vector<BadInput> badCommandLineInputs() {
  const std::string& plan = kPlanCommand;
  const std::string& bench = kGridBenchCommand;
  const std::string& scen8 = kScen8;
  const std::string map8 = freeMap8();
  return {
      // Command line and files.
      {"scenario_missing", "plan {out}/none.yaml --out {out}", "", "", 2,
       "cannot open scenario file"},
      {"set_without_value", "plan {in} --set planner --out {out}", kValid, "", 2,
       "expected key=value"},
      {"out_under_regular_file", "plan {in} --out /etc/passwd/x", kValid, "", 2,
       "cannot create folder"},
      // --set values are placed at the assignment, not at "line 1" of the file.
      {"set_parameter_wrong_type", "plan {in} --set planner.resolution=fast --out {out}", kValid,
       "", 2,
       "{in}: --set planner.resolution=fast, key planner.resolution: 'resolution' must be a "
       "number, got 'fast'"},
      {"set_value_wrong_type", "plan {in} --set sim.timestep=abc --out {out}", kValid, "", 2,
       "{in}: --set sim.timestep=abc, key sim.timestep: must be a number, got 'abc'"},
      {"set_unknown_key", "plan {in} --set wrld.x=1 --out {out}", kValid, "", 2,
       "{in}: --set wrld.x=1, key wrld: unknown key 'wrld' (did you mean 'world'? allowed: "},
      // --set on list elements: an index past the end, or into something that is not a list.
      {"set_list_index_out_of_range", "plan {in} --set 'vehicles[3].goal=[5,5,1]' --out {dir}/new",
       kValid, "", 2,
       "command line: --set vehicles[3].goal=[5,5,1]: index 3 is out of range: vehicles has 1 "
       "element (indices 0 to 0)"},
      {"set_index_into_a_mapping", "plan {in} --set 'planner[0].name=rrt' --out {dir}/new", kValid,
       "", 2, "--set planner[0].name=rrt: planner is not a list, so it has no element planner[0]"},
      {"set_malformed_index", "plan {in} --set 'vehicles[x].goal=[5,5,1]' --out {dir}/new", kValid,
       "", 2, "'vehicles[x]': a list element is written name[N], N a whole number from 0"},
      {"set_list_element_bad_value", "plan {in} --set 'vehicles[0].goal=[5,5]' --out {dir}/new",
       kValid, "", 2,
       "{in}: --set vehicles[0].goal=[5,5], key vehicles[0].goal: must be a list of 3 numbers"},
      // NUL and other control bytes quoted from the input are escaped, not echoed raw (a NUL
      // cut the message short).
      {"planner_name_with_nul", plan, withPlanner("planner: {name: \"te\\0st\\x1b\"}\n"), "", 2,
       "unknown planner 'te\\x00st\\x1b' (known: "},
      // MovingAI maps and scenarios.
      {"map_short_row", bench, mapText(3, 2, "...\n..\n"), scen8, 2, "expected 3"},
      {"map_huge_dimensions", bench, mapText(99999999, 99999999, ""), scen8, 2,
       "height must be between"},
      {"map_nul_character", bench, mapText(3, 2, std::string("..\0\n...\n", 8)), scen8, 2,
       "line 5, column 3: unknown map character '\\x00'"},
      {"map_truncated", bench, mapText(8, 8, "........\n........\n"), scen8, 2,
       "expected 8 map rows, found 2"},
      {"scen_outside_map", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\t99\t3\t5.0\n", 2,
       "outside the stated map size"},
      {"scen_nan_length", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\t7\t7\tnan\n", 2,
       "optimal_length 'nan' is not a number"},
      {"scen_truncated_line", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\n", 2,
       "expected 9 fields"},
      {"mapf_too_many_agents", "mapf {in} {in2} --agents 100 --planner cbs --out {out}", map8,
       scen8, 2, "fewer than the 100 agents"},
      {"mapf_range_backwards", "mapf {in} {in2} --agents 10:5:1 --planner lacam --out {out}", map8,
       scen8, 2, "--agents 10:5:1: STOP is below START"},
      {"mapf_range_not_numbers", "mapf {in} {in2} --agents 1:x:2 --planner lacam --out {out}", map8,
       scen8, 2, "expected N or START:STOP:STEP"},
      {"mapf_benchmark_unknown_planner",
       "mapf {in} {in2} --agents 1:3:1 --planner lacam,teleport --out {out}", map8, scen8, 2,
       "unknown multi-robot planner 'teleport'"},
  };
}

}  // namespace cosim::test
