// weft-panel-sim: firmware-host's panel simulator (sim/panel_sim_cli.h) with the kiosk's panel
// config reader, so --panel-config takes the USB VID/PID from the config the kiosk reads.
#include <fstream>
#include <sstream>

#include "panel/panel_config.h"
#include "sim/panel_sim_cli.h"

int main(int argc, char** argv) {
  return weft::sim::panel_sim_main(argc, argv, [](const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open panel config '" + path + "'");
    std::stringstream json;
    json << f.rdbuf();
    const auto config = weft::input::parse_panel_config(json.str(), path);
    weft::sim::UhidIdentity id;
    id.vendor_id = config.hid.vendor_id;
    id.product_id = config.hid.product_id;
    return id;
  });
}
