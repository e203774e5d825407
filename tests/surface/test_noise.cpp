// POV-Ray 3.7's noise, turbulence and the patterns built on them, against values POV-Ray itself printed at
// these points (#write of f_noise3d, vturbulence and pattern functions; docs/povray-noise.md tells how).
#include <catch2/catch.hpp>

#include <cmath>
#include <iterator>

#include "raytrace/surface/noise.hpp"
#include "raytrace/surface/pattern.hpp"

namespace rt {
namespace {

// Six points near the origin, four farther out, one beyond x = -10000 (where the lattice's shift by 10000
// turns negative) and a lattice point.
const glm::dvec3 kPoints[] = {
    {-0.4762, 0.5977, 4.2421},
    {-0.3435, 0.0784, 0.8738},
    {-3.1534, 0.1191, 1.2988},
    {2.9298, -4.0588, -1.966},
    {-4.0933, 3.0964, 1.9344},
    {-4.5812, 4.8219, 4.6476},
    {18.4707, 13.8675, -41.1007},
    {-58.1999, 3.4058, -52.8539},
    {-37.175, -30.9668, -56.3901},
    {-4.3279, -7.1363, 41.0913},
    {-12345.678, 23.25, -0.5},
    {3.0, -2.0, 7.0}};

constexpr double kNoise1[] = {
    0.4194049753959088, 0.5430105933239014, 0.9573299794957869, 0.508270654833117,
    0.3921482629886519, 0.509347630039657, 0, 0.1126939455530191,
    0.3926445378392746, 0.2109641629167835, 0.2803490205159974, 0.2998095};

constexpr double kNoise2[] = {
    0.4760541202190427, 0.5366030515457663, 0.7395598142008919, 0.5195854904896133,
    0.4627022610122817, 0.5201130530625329, 0.2683549005792424, 0.3258099371923095,
    0.4629453641361788, 0.3739481751006146, 0.4079367514154607, 0.41746958055069};

const glm::dvec3 kVectorNoise[] = {
    {-0.08059502460409119, 0.0384670354464601, -0.3397060767771825},
    {0.0430105933239015, -0.6734663294729881, -0.1498906312458909},
    {0.4573299794957869, 0.2587615784366099, 0.1612986540038585},
    {0.008270654833116901, -0.1118565472776681, -0.5121758990176006},
    {-0.1078517370113481, 0.3634754775575171, -0.0977643234264348},
    {0.009347630039657001, 0.3220455096678675, 0.1467345645545375},
    {-0.5045957431008119, -0.1011886632769768, 0.1406753100441715},
    {-0.3873060544469809, -0.3877475708651417, 0.0528972344412267},
    {-0.1073554621607255, -0.0789522294036227, -0.1685751525631102},
    {-0.2890358370832165, -0.2805984696096853, -0.020437654233939},
    {-0.2196509794840026, 0.008874410364360701, -0.0257449123687818},
    {-0.2001905, 0.4806515, 0.3672005}};

const glm::dvec3 kTurbulence[] = {
    {0.1067461132289888, -0.0376348459082752, -0.3649162883365694},
    {-0.0183023865351926, -0.4918505354203028, -0.3223129579422677},
    {0.4373319588040852, 0.1264560481476157, 0.2184749079142646},
    {0.1320737343308773, 0.0804092119458866, -0.4451392425344263},
    {-0.2844708364867058, 0.662834395669617, -0.5046971230053569},
    {-0.1694525886540149, 0.1861093293155211, -0.1244624989040223},
    {-0.6468636000603525, -0.1635317399601235, 0.2290579153738975},
    {0.0435373126300318, -0.1562033722226402, -0.0413606540395084},
    {-0.3093917919828942, -0.453086495131805, -0.3166371884763443},
    {-0.2726980811950493, -0.0433863758812957, -0.2213919354144842},
    {-0.3965600465941918, -0.0622448367586849, 0.0715606096846981},
    {-0.2686354843258842, 0.1216984149203268, 0.281160846396366}};

// function { pattern { … } } at the same points, POV-Ray's default noise_generator 2 unless named.
constexpr double kBozo[] = {
    0.4760541202190427, 0.5366030515457663, 0.7395598142008919, 0.5195854904896133,
    0.4627022610122817, 0.5201130530625329, 0.2683549005792424, 0.3258099371923095,
    0.4629453641361788, 0.3739481751006146, 0.4079367514154607, 0.41746958055069};

constexpr double kGranite[] = {
    0.4825682729638164, 0.2203821904695763, 0.1623807698625863, 0.3187232108787209,
    0.1275150640413209, 0.1732731505346611, 0.5904238505413811, 0.665039693687048,
    0.6047377958576702, 0.2818066341288234, 0.306404120353357, 0.3111555158614887};

constexpr double kWrinkles[] = {
    0.4250457348714551, 0.6100300255039135, 0.7023374769373182, 0.5278436919082373,
    0.4164143105812673, 0.5966561230342198, 0.1543506321529682, 0.4948756732460861,
    0.3807619901198498, 0.2844281578516402, 0.4725334198814519, 0.3863157132383022};

constexpr double kAgate[] = {
    0.9880630220603375, 0.0024668026128942, 0.9534225384954652, 0.5453681281347057,
    0.1485027627592082, 0.2312882318358961, 0.5282220357469594, 0.5970990346956887,
    0.7820600211511316, 0.4083396550314772, 0.7384029384612356, 0.9762403514778989};

constexpr double kGranite1[] = {
    0.5292279588859343, 0.1981893985684925, 0.1905180404608252, 0.3540620364648274,
    0.1246657658885556, 0.1924852603112909, 0.6082729793820058, 0.6858732187969514,
    0.587792164242693, 0.3163809727286676, 0.3256320868015123, 0.2987703781249999};

constexpr double kWrinkles1[] = {
    0.3918642055577036, 0.5806381803978675, 0.6748571642563194, 0.496749874412258,
    0.383012957571125, 0.5669873078737838, 0.1179036313552681, 0.4655921807156408,
    0.3518805496308483, 0.248293569395205, 0.4402942095323497, 0.3522910633789062};

constexpr double kBozoTurbulence[] = {
    0.5239841533255235, 0.5334473865638821, 0.6614622641347889, 0.4936885476741441,
    0.5299193502787857, 0.5377940295073642, 0.4916078398866357, 0.3926040807634713,
    0.4874046147635586, 0.2507664193996071, 0.4124493479855202, 0.4385394395420849};

constexpr double kWood[] = {
    0.0498201455249294, 0.1168283490522974, 0.8344128767889032, 0.9444697525376777,
    0.8936639723151099, 0.478281773925668, 0.0591593896967813, 0.0148464079537036,
    0.0133288140964396, 0.4618925276097072, 0.9692630543690406, 0.547965888598398};

constexpr double kMarble[] = {
    0.09147030217047949, 0.332056937394937, 0.7476114227519033, 0.3858606395639348,
    0.4344502408260125, 0.0534738543894409, 0.7350197054871925, 0.0025887440280745,
    0.3903072817914879, 0.1706477185970354, 0.8887899850777434, 0.5496474850719362};

constexpr double kDents[] = {
    0.1078869672110173, 0.1545110038932262, 0.404501292838987, 0.1402720178502434,
    0.09906149207920451, 0.1406997285841237, 0.0193254044496664, 0.0345854139774296,
    0.0992177144396353, 0.0522918798344718, 0.0678857310590861, 0.072756953633555};

constexpr double kLeopard[] = {
    0.06883625639917031, 0.0287086460967569, 0.1329482782901657, 0.0007326285965715,
    0.3576861273618027, 0.1112232563292849, 0.0804815527319311, 0.353351949855861,
    0.1326239709527803, 0.0006137688898585, 0.058738803395015, 0.0013737109403033};

constexpr double kCrackle[] = {
    0.3295302783837101, 0.076376640675989, 0.0501828488051443, 0.2572592715098405,
    0.007942834001589299, 0.0716197578130556, 0.0514669470984093, 0.047660625310789,
    0.383723560440311, 0.4613018801954609, 0.2940336020934141, 0.4466888562323816};

constexpr double kCrackleMetric1[] = {
    0.2754280512943865, 0.1112736162055283, 0.0930032655172051, 0.1767616125825788,
    0.0399541095830505, 0.1672296202357852, 0.024144493372745, 0.0314126449964931,
    0.3097000131864149, 0.7493335313629359, 0.4795804165769368, 0.8536187275312841};

constexpr double kCrackleMetric3[] = {
    0.3494624946245652, 0.0703586955671219, 0.0123572608192816, 0.2705359568597755,
    0.0312027681802466, 0.0402493363402956, 0.0606142151841047, 0.0574163948553825,
    0.4159167935711104, 0.3955357623174706, 0.2721973948704438, 0.3483244160913647};

constexpr double kCrackleForm[] = {
    0.1489497561309445, 0.2177731218153171, 0.2392283989776816, 0.2088856764579114,
    0.3266523125364817, 0.3743199501536563, 0.3766205239046608, 0.2541196100032979,
    0.1378710015818564, 0.0504159569346112, 0.1686293300406257, 0};

constexpr double kCrackleOffset[] = {
    0.2729569704994428, 0.0529320087658949, 0.0370195437738932, 0.2162719632424507,
    0.006166028386264, 0.0498411423543275, 0.0430210400870094, 0.0360545443950727,
    0.2938046825742194, 0.2983695671546102, 0.2377363424134441, 0.2940187970112363};

constexpr double kCrackleSolid[] = {
    0.4197922528080516, 0.457736399668367, 0.7595888133016725, 0.5394435656695185,
    0.5755467885370784, 0.4673212588793491, 0.662768545186609, 0.225508135753372,
    0.5373016638406201, 0.4590826095943943, 0.3493598796275929, 0.3430013292190008};

constexpr double kCells[] = {
    0.1476082224398851, 0.5669548758305609, 0.4782246532849967, 0.9343062515836209,
    0.5114089341368526, 0.5860920653212816, 0.1272660314571112, 0.2528233490884304,
    0.6202600349206477, 0.8830980900675058, 0.9328535695094615, 0.3462607159744948};

constexpr double kSpiral1[] = {
    0.8274554345424834, 0.3689626799934431, 0.6863636419863051, 0.3382520600965941,
    0.0076177864104419, 0.1614243618419411, 0.0540114328831507, 0.6675879024643501,
    0.5746586083773999, 0.1765928891180959, 0.3255235789834914, 0.0746907127474903};

constexpr double kSpiral2[] = {
    0.8165559276221532, 0.4426421181073474, 0.9384493720244746, 0.6880745916455355,
    0.2804626452896724, 0.0207511038086614, 0.3018286715438094, 0.2636078720136363,
    0.6169513218234317, 0.0464290646760754, 0.4981916307003504, 0.9384988745670038};

// noise_generator 3 (global_settings' in POV-Ray's run): the noise, and the patterns whose sums depend on the
// generator, with the same modifiers as above.
constexpr double kNoise3[] = {
    0.9097456744535768, 0.313743449470324, 0.6412497516190048, 0.4971134100486281,
    0.541662650520613, 0.7564669959522956, 0.3240813443975229, 0.4912258119656659,
    0.5228019597539789, 0.474673533433763, 0.687182837801608, 0.5240268174894488};

constexpr double kGranite3[] = {
    0.5820294839943064, 0.781855725356861, 0.2972099877571722, 0.1330522158640063,
    0.2829250000421946, 0.2593069840870273, 0.3410751204208369, 0.4059435246583216,
    0.427652584403855, 0.6225536466877379, 0.164386609839005, 0.0540434890634499};

constexpr double kWrinkles3[] = {
    0.7267880837421846, 0.253623817582619, 0.772832320966774, 0.4495284932506985,
    0.5230824995186639, 0.6403435349758163, 0.2639872204027578, 0.5436654307045398,
    0.547927467506579, 0.5812804744283385, 0.6833850995193759, 0.5201748209543233};

constexpr double kAgate3[] = {
    0.2737090924485719, 0.9999911112163827, 0.7888468592337577, 0.8111739927195255,
    0.054412107989126, 0.3975581317149593, 0.8805381199926109, 0.4103450105578317,
    0.0906604958823507, 0.6202879176003305, 0.9535246439902624, 0.8977810894943821};

constexpr double kMarble3[] = {  // with ramp_wave, as kMarble
    0.4180447261760197, 0.0151543009951218, 0.5970503013997801, 0.3755745613445898,
    0.3475146850584272, 0.2071104889091777, 0.7482467255636349, 0.5974404690969881,
    0.1432253072762197, 0.3100795052631589, 0.1335460295863946, 0.6396058700048948};

constexpr double kBozoTurbulence3[] = {
    0.915561078480838, 0.3904348919198135, 0.6234611352748896, 0.4631043909050822,
    0.5455985365714113, 0.7635302682452474, 0.4160623040650627, 0.4637905833137059,
    0.6205560427531669, 0.4920686660941082, 0.6552772148394101, 0.5827295949106377};

constexpr double kExact = 1e-11;  // POV-Ray printed 16 decimals; the sums agree to the last few bits

TEST_CASE("noise: both generators and the vector noise give POV-Ray's values", "[noise]") {
  for (size_t i = 0; i < std::size(kPoints); ++i) {
    INFO(i);
    CHECK(noise(kPoints[i], NoiseGenerator::Original) == Approx(kNoise1[i]).margin(kExact));
    CHECK(noise(kPoints[i], NoiseGenerator::RangeCorrected) == Approx(kNoise2[i]).margin(kExact));
    const glm::dvec3 v = vectorNoise(kPoints[i]);
    for (int c = 0; c < 3; ++c) CHECK(v[c] == Approx(kVectorNoise[i][c]).margin(kExact));
  }
}

TEST_CASE("noise: generator 3 gives POV-Ray's values, and the vector noise is the same for every generator", "[noise]") {
  for (size_t i = 0; i < std::size(kPoints); ++i) {
    INFO(i);
    CHECK(noise(kPoints[i], NoiseGenerator::Perlin) == Approx(kNoise3[i]).margin(kExact));
  }
  // 0.4925 at a corner of its lattice, which lies 0.0231572… below the integers.
  const double corner = -(0xBDB432p-29);
  CHECK(noise({corner, 1 + corner, 2 + corner}, NoiseGenerator::Perlin) == 0.4925);
  CHECK(noiseGeneratorOf(3.5) == NoiseGenerator::Perlin);
  CHECK(noiseGeneratorOf(2) == NoiseGenerator::RangeCorrected);
  CHECK(noiseGeneratorOf(1) == NoiseGenerator::Original);
}

TEST_CASE("noise: turbulence with POV-Ray's single-precision omega and lambda", "[noise]") {
  Turbulence t;
  t.octaves = 4;
  t.omega = 0.6f;
  t.lambda = 2.3f;
  for (size_t i = 0; i < std::size(kPoints); ++i) {
    INFO(i);
    const glm::dvec3 v = turbulentOffset(kPoints[i], t);
    for (int c = 0; c < 3; ++c) CHECK(v[c] == Approx(kTurbulence[i][c]).margin(kExact));
  }
}

void checkPattern(const char* name, const PatternArgs& args, const double* expected, double margin = kExact) {
  const PatternKind* kind = patternKind(name);
  REQUIRE(kind != nullptr);
  const auto pattern = makePattern(*kind, args);
  for (size_t i = 0; i < std::size(kPoints); ++i) {
    INFO(name << " at point " << i);
    // POV-Ray's pattern functions wrap the value as a ramp wave does.
    double v = std::fmod(pattern->value(kPoints[i]), 1.00001);
    if (v < 0) v -= std::floor(v);
    CHECK(v == Approx(expected[i]).margin(margin));
  }
}

TEST_CASE("noise patterns: bozo, granite, wrinkles, agate, dents and leopard", "[noise]") {
  PatternArgs a;
  checkPattern("bozo", a, kBozo);
  checkPattern("spotted", a, kBozo);
  checkPattern("bumps", a, kBozo);
  checkPattern("dents", a, kDents);
  checkPattern("leopard", a, kLeopard);
  checkPattern("granite", a, kGranite);
  checkPattern("wrinkles", a, kWrinkles);
  a.agateTurbulence = 0.5;
  checkPattern("agate", a, kAgate);
  PatternArgs original;
  original.noise.own = NoiseGenerator::Original;
  checkPattern("granite", original, kGranite1);
  checkPattern("wrinkles", original, kWrinkles1);
}

TEST_CASE("noise patterns: turbulence displaces bozo, and marble and wood take it their own ways", "[noise]") {
  PatternArgs a;
  a.turbulence.amount = {0.5, 0.2, 0.1};
  checkPattern("bozo", a, kBozoTurbulence);
  a.turbulence.amount = {0.5, 0.3, 0.2};
  checkPattern("wood", a, kWood);
  a.turbulence = Turbulence{};
  a.turbulence.amount = glm::dvec3(0.5);
  a.turbulence.octaves = 3;
  a.turbulence.omega = 0.7f;
  a.turbulence.lambda = 2.5f;
  checkPattern("marble", a, kMarble);
}

TEST_CASE("noise patterns: granite, wrinkles, agate, marble and turbulence with generator 3", "[noise]") {
  PatternArgs a;
  a.noise.own = NoiseGenerator::Perlin;
  checkPattern("bozo", a, kNoise3);
  checkPattern("granite", a, kGranite3);
  checkPattern("wrinkles", a, kWrinkles3);
  a.agateTurbulence = 0.5;
  checkPattern("agate", a, kAgate3);
  a.turbulence.amount = {0.5, 0.2, 0.1};
  checkPattern("bozo", a, kBozoTurbulence3);
  a.turbulence = Turbulence{};
  a.turbulence.amount = glm::dvec3(0.5);
  a.turbulence.octaves = 3;
  a.turbulence.omega = 0.7f;
  a.turbulence.lambda = 2.5f;
  checkPattern("marble", a, kMarble3);
}

TEST_CASE("noise patterns: crackle's forms, metrics, offset and solid cells, and cells", "[noise]") {
  PatternArgs a;
  checkPattern("crackle", a, kCrackle);
  checkPattern("cells", a, kCells);
  a.crackle.metric = 1;  // reaches past the 27 cubes around the point
  checkPattern("crackle", a, kCrackleMetric1);
  a.crackle.metric = 3;
  checkPattern("crackle", a, kCrackleMetric3);
  a.crackle = CrackleArgs{};
  a.crackle.form = {1, -1, 0.5};
  checkPattern("crackle", a, kCrackleForm);
  a.crackle = CrackleArgs{};
  a.crackle.offset = 0.5;
  checkPattern("crackle", a, kCrackleOffset);
  a.crackle = CrackleArgs{};
  a.crackle.solid = true;
  checkPattern("crackle", a, kCrackleSolid);
}

TEST_CASE("patterns: spiral1's arms, and its turbulence refused", "[noise]") {
  PatternArgs a;
  a.vector = glm::dvec3(3);  // spiral1 3
  a.hasVector = true;
  checkPattern("spiral1", a, kSpiral1, 1.1e-5);  // the wrap's 1e-5 where a value lands on a whole number
  // On the z axis the angle counts as 0: the value is z (POV-Ray's triangle wave of it gives 0.6 at z = 0.3).
  CHECK(makePattern(*patternKind("spiral1"), a)->value({0, 0, 0.3}) == Approx(0.3).margin(kExact));
  CHECK_FALSE(patternKind("spiral1")->turbulenceDrawn);
}

TEST_CASE("patterns: spiral2's arms and rings, and its turbulence refused", "[noise]") {
  PatternArgs a;
  a.vector = glm::dvec3(3);  // spiral2 3
  a.hasVector = true;
  checkPattern("spiral2", a, kSpiral2);
  // On the z axis the angle counts as 0: the value is twice z's triangle wave (0.6 at z = 0.3, as POV-Ray gives).
  const auto axis = makePattern(*patternKind("spiral2"), a);
  CHECK(axis->value({0, 0, 0.3}) == Approx(0.6).margin(kExact));
  CHECK_FALSE(patternKind("spiral2")->turbulenceDrawn);
}

TEST_CASE("noise: the scene's generator is read when the pattern is drawn", "[noise]") {
  auto scene = std::make_shared<NoiseGenerator>(NoiseGenerator::RangeCorrected);
  PatternArgs a;
  a.noise.scene = scene;
  const auto bozo = makePattern(*patternKind("bozo"), a);
  CHECK(bozo->value(kPoints[0]) == Approx(kNoise2[0]).margin(kExact));
  *scene = NoiseGenerator::Original;
  CHECK(bozo->value(kPoints[0]) == Approx(kNoise1[0]).margin(kExact));
}

}  // namespace
}  // namespace rt
