// Tests of viscoroll/special/bessel_ratio.hpp: I_1/I_0, I_2/I_0, K_1/K_0 and e^{-x} I_nu, e^{x}
// K_nu.
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>
#include <viscoroll/special/bessel_ratio.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bessel_ratio {

namespace {

using viscoroll::special::bessel_i0_scaled;
using viscoroll::special::bessel_i1_over_i0;
using viscoroll::special::bessel_i1_scaled;
using viscoroll::special::bessel_i2_over_i0;
using viscoroll::special::bessel_k0_scaled;
using viscoroll::special::bessel_k1_over_k0;
using viscoroll::special::bessel_k1_scaled;
using Mp50 = boost::multiprecision::cpp_bin_float_50;

// Reference values at x = m 2^e (exact in float and wider), to 60 significant digits, in the order
// I1/I0, I2/I0, e^-x I0, e^-x I1, K1/K0, e^x K0, e^x K1. Produced by mpmath 1.3 with mp.dps = 100:
//   I1/I0 = besseli(1,x)/besseli(0,x), I2/I0 = besseli(2,x)/besseli(0,x), exp(-x)*besseli(0,x),
//   exp(-x)*besseli(1,x), besselk(1,x)/besselk(0,x), exp(x)*besselk(0,x), exp(x)*besselk(1,x);
//   for x > 1e4 from the Hankel series DLMF 10.40.1-2 summed until a term is below 1e-90 (the
//   series' own error there is e^{-2x} < 1e-8000); nstr(value, 60).
// The points straddle every switch: x_T = 10 (float), 21 (double), 24 (long double), 60 (50
// digits), the I_2/I_0 series limit 4, and the small-argument branch sqrt(eps) of I_1/I_0.
struct Reference {
  long m;
  int e;
  const char* value[7];
};
// clang-format off
const Reference references[] = {
    {1, -100, {"3.94430452610505902705864282641393114836603217554511502385139e-31", "7.77876909732642713393008006722515530073781521090145891637639e-62", "9.99999999999999999999999999999211139094778988194588271434718e-1", "3.94430452610505902705864282641081964072710160469154299182451e-31", "1.82577954843992150068695554955826765516327931012842940018141e+28", "6.94306495716529433905339321772482020696545312309275675091405e+1", "1.26765060022822940149670320537699999999999999999999999999997e+30"}},
    {1, -60, {"4.33680868994201773602981120347976684529529347075009221708061e-19", "9.40395480657830006374989229777796542137019957412113866588393e-38", "9.99999999999999999132638262011596453358275047698744634412481e-1", "4.33680868994201773226822928084844682224232572713835274475185e-19", "2.76448405328807433029324834174310146273871674738778665871501e+16", "4.17047623492551310500177624725096343789991049270791238176625e+1", "1.15292150460684697699999999999999998213028285767546780419306e+18"}},
    {1, -40, {"4.54747350886464118957519484230225967108499681250544993417754e-13", "1.03397576569128459358926072254000236204016401113084065094234e-25", "9.99999999999090505298227692147544375394790993337367112700281e-1", "4.54747350886050528651243252511434460011683396477116599719239e-13", "3.94913722454886705787707416302092470360598653736757348712015e+10", "2.78418187380815468121300067405739113775100750792416479822193e+1", "1.09951162777699999999998756638036043946231321556324012261389e+12"}},
    {1, -26, {"7.45058059692382791820484686174308893510584014844329121315843e-9", "2.77555756156289124834281546957447587165275119735734033759876e-17", "9.99999985098838972685796065139135796171651021407277597313561e-1", "7.45058048590152669646010445878300791252769672032280771527922e-9", "3.69995361180840233763710131392142852719324883992048929660313e+6", "1.81377584804906523551905882243315122203924936420068836969866e+1", "6.71088649999998685884588735239302098848699363747363862973329e+7"}},
    {3, -13, {"1.83105465680455450126034343166207520759926084676616179845281e-4", "1.67638059683783511071882853266231236762194401698049707000841e-8", "9.99633889624877705876965847431011653601688030269566972767935e-1", "1.83038428869728236228669755516005533179159541338419603155097e-4", "3.40132772298581734735743420157395002075463872087444664622147e+2", "8.03117344205370664607674249480082878187586337126599548431746", "2.73166528765647031269693261713355206468762380328555101912227e+3"}},
    {1, -12, {"1.22070311590505307262089773571152627897465419405298031254e-4", "7.45058052290896057490511767226396328423179852796722935866187e-9", "9.99755904072420931104330558285185036552717442460054874179477e-1", "1.22040514724567756904188475376428518714763369796822120479376e-4", "4.85670579554580650793605614435367434833383757815491729305192e+2", "8.43575708257259997941750651699909338104926178670279532345559", "4.09699903127469309432896882436510123858505538715604068381681e+3"}},
    {1, -6, {"7.8122615911217681918013485263569309213320367611346811187302e-3", "3.05163364136714494273886263128420694992945747608168025346113e-5", "9.84556526816158573822431615252706950688815316613731478825108e-1", "7.69161313873412481243494010304553653699032242288555280938537e-3", "1.49615561147173933816596717561261419595492543538455073527468e+1", "4.34246015814285079710694630150737198094461072978919789227818", "6.4969961331978828406417698681932304421184194277627563970998e+1"}},
    {1, -2, {"1.24033501917924714616564362986856562670431157313873026803697e-1", "7.73198465660228306748509610514749863655074148901578557042217e-3", "7.91017162139719363886188333232469688858142803089804632161587e-1", "9.81126286973682466742034223380163188140636957333012539638367e-2", "2.43075547441254651262829905006611320526088576431223102689995", "1.97933384859856868363873942154370648077861014351723775106834", "4.81127658817102533288632926284273611513882283242561773681815"}},
    {3, -2, {"3.50886913213561811471834150582506960088455326188070580118274e-1", "6.43015647638351694084422651133147730974524634984784530179352e-2", "5.41165219203495323140227553374715778408820428099538919799979e-1", "1.89887793304855017265262582588731354555741741730502209775638e-1", "1.5552043959447865038495212871288047318309179402229523102456", "1.29260299776396167761921040474690561212650248394362620236957", "2.01026186433392224076779309312297586363192393713209482707344"}},
    {1, 0, {"4.46389965896534507047681795192642669776253147400387822861199e-1", "1.07220068206930985904636409614714660447493705199224354277602e-1", "4.65759607593640436501901529563209998732865911828799168039611e-1", "2.07910415349708448869354685507950449869285568565795025785698e-1", "1.42962539826040175802810802345036563008001701819266298345903", "1.14446307980689501469904130356683152023369590694769495138944", "1.63615348626325824651331113126452640474875222809487525088364"}},
    {3, -1, {"5.96133238831290705187759308542445856263397373411911527993019e-1", "2.05155681558279059749654255276738858315470168784117962675974e-1", "3.6743360905415833923824150692732825483235443076702540912113e-1", "2.19039387420925672115110112328838711477116473396104374528827e-1", "1.29738345916723455434546186047268251948711689981945036813474", "9.58210053294896496416754894901029707768462587929083853220134e-1", "1.24316587355255299480026384489118120225142945822293634342155"}},
    {5, -1, {"7.64996747588809917277187751479936595948169858185133137804411e-1", "3.88002601928952066178249798816050723241464113451893489756471e-1", "2.70046441612202739560098656519673238242065242213888143785057e-1", "2.06584649531266554214643690449819136685275482591620536355805e-1", "1.18514380364349375214202402852918294449541562914327914307183", "7.59548690328099578693718979251300146702248754679680072065933e-1", "9.00174423907878089129560957070865989535835581048139674862932e-1"}},
    {127, -5, {"8.62310251606037385011908553221045879957886557433631365282275e-1", "5.65449951946563837474313799951598926635395750584626713558539e-1", "2.0789057909103320638068768287776341827237995985075446805506e-1", "1.79266177562513658964406714743309470115099370903726795429667e-1", "1.11951766736786733327798345599375461515555062189048844466832", "6.11569060429359604257624598034047946671045738532779229895132e-1", "6.84662367966234961838009590466084692134278934747360374222047e-1"}},
    {1, 2, {"8.63522611024550582854649070870985088116286602231357707418941e-1", "5.68238694487724708572675464564507455941856698884321146290529e-1", "2.07001921223986697895080847960271803066927307698345724561094e-1", "1.78750839502435327013709443322919421054425538269893035292652e-1", "1.11862555787740112716340524717106923404757226951289759629085", "6.09297669256695269256971041160880891203760484223828472058925e-1", "6.8157594518567098333570432483874184011776399588582821404923e-1"}},
    {17, -2, {"8.72490891417495419324805676209201316526099357021377907043835e-1", "5.89416051097649214435385564136846439281835596695822161391137e-1", "2.00287869552257090685601065517551032081606073054779700443727e-1", "1.7474934184575982819773942790188465789441627846750000907453e-1", "1.11194333589786196595678984013901934689097233136793227842769", "5.91997283444392997474197988535742088885907437251865713164521e-1", "6.58267434195630481416567938956642768457538854188658919394915e-1"}},
    {13, -1, {"9.1948802947494823644273986175083686170577898058845750445148e-1", "7.17080606315400542633003119461280965628991082895859229399545e-1", "1.59804849017632246344891234535415608142008525176861390006232e-1", "1.46938645723764291654429240521749426298409429699045357776319e-1", "1.07433567864193804009412697129225143060231572265205992281642", "4.8284744139975632108042277884723005479563519235409891326156e-1", "5.18740233636730616439345095126632158518540442279981651440336e-1"}},
    {319, -5, {"9.48433714473188063465984982507844395840484551188824167729944e-1", "8.09718627817291423003689533289962252872128491297539978888036e-1", "1.28039167119057177892059610126608092106736025751163144506068e-1", "1.2143666286878068494338907258505385738208922394031381264344e-1", "1.04900859593019677180750336122507151331177111659804748539316", "3.92231266114055562817073158837171421394938180795195699876044e-1", "4.1145396974622879324393642437568750350077971193712901649562e-1"}},
    {5, 1, {"9.48599825954845958971301857835032007087886792060910817852557e-1", "8.10280034809030808205739628432993598582422641587817836429489e-1", "1.27833337163428607323050287645003038350329424071917126844686e-1", "1.21262681384455518718954970330323558576282152623394152591458e-1", "1.0488587228891769387050235893717052930269439809083519743577", "3.91631934436598665733921057536392148255870621316910068871008e-1", "4.10766570595788751130046941317757333001223146186776875201483e-1"}},
    {21, -1, {"9.51118787719111495410375332060831550330994841765814490700925e-1", "8.188345166249311437313570796074606570798105063303210493903e-1", "1.24669669459086165031263530421641717270883395821364683998904e-1", "1.18575664881268371850057836603604702443524773707377025016049e-1", "1.04657974546479629082403676153418710382932623676139191914199", "3.8240181259832663050156529683854585737990390958503333751366e-1", "4.00213991694433416477128059789791206140309579528182429422028e-1"}},
    {31, -1, {"9.67184143782611044282831529838556738193964412433143123081889e-1", "8.75202045963534058802215286472444291845940075815078306699111e-1", "1.02180506523292095718067919071637079803475000044764763017935e-1", "9.88273657130037680512957962496210582470424073476471306258954e-2", "1.03176834730140001315285472327755419041291156637863423482419", "3.15862288933721661955467466794825568732866688971276229631639e-1", "3.25896711827983289752999963647712957002153133025577326196599e-1"}},
    {671, -5, {"9.75856017453072428272931951419311980963974056361714622531598e-1", "9.06922823968708442012715879447338350548890701032563731979102e-1", "8.76552206904850385281145229656834275624739402050693885323083e-2", "8.55388745719868831851751842398977834174978615802537949639363e-2", "1.02357335231982121469270003564936224102673719742969453084563", "2.72109436794934150005712481333135856148576440562150791727037e-1", "2.78523968418049255145720269139659136877638072083405345456911e-1"}},
    {21, 0, {"9.75892413886218191346143260525809243942965139102106117794183e-1", "9.07057865344169696062272070426113405338765224847418464971983e-1", "8.75891596542278550490887566111165414417505437418480595822662e-2", "8.54775964452297737659678526532359706790356854957579198685315e-2", "1.02353865907026598865990447032446781861595620373504494634183", "2.71909203967015335655663389832875216149325555100065466962445e-1", "2.78309582017262325931902542976133087564353177099935931693434e-1"}},
    {43, -1, {"9.76460177166567752171652736141551955508572109238379882044028e-1", "9.09166495147296023053799745475204469255016547977825127251718e-1", "8.65520976836608542272949850840723563179204555255270707402881e-2", "8.45146766383255560836643593716371424420346380911853229009517e-2", "1.02299714008313265054561529332000161981455021276313206454659", "2.68764438451255523676903778239288172090232285716972044570462e-1", "2.74945251891683530271531604623952094985971853063414481422184e-1"}},
    {767, -5, {"9.78912197290661176302103534601215893957212193037967632553527e-1", "9.18317626301691896631897488638229703763674601884706742524869e-1", "8.19222212531573749166474167431971252524906816227892977790263e-2", "8.01946616138599882611319235077650159190992786195154062398937e-2", "1.02065144764154590301858828491809248260767732524844304754658", "2.54693383580818772792384882593584376309682437855359108461683e-1", "2.59953170656486218657527927251262674760779643046825462084663e-1"}},
    {3, 3, {"9.78939964513962004306572302166403741360801047635629278333953e-1", "9.18421669623836499641118974819466354886599912697030893472171e-1", "8.18682883340306136088879523806553663373082253231037071755602e-2", "8.01441392765347384224894273803129024658063520042824811284432e-2", "1.02062481915085569572349989008516438019590226874024123698923", "2.5452917420902205838747191508765989419656386945163172640407e-1", "2.59778792395699782165950882655994019305652773584692006444773e-1"}},
    {51, -1, {"9.80191880579823152506772074758232551605390594360415080629847e-1", "9.23122205444719752744566896097393525364283090638398817205502e-1", "7.93985245479706204660660864660315217436717271792924971889157e-2", "7.78257890919385754671904488773296704185955688914182503403698e-2", "1.01942272030783451528429578555522704585175898447440976572293", "2.47002351741646936483365944218077141003920125205459785056148e-1", "2.5179980933490230649201116322613325233426398044618130755657e-1"}},
    {161, -2, {"9.87498486748809379412128710151152518512469971713123950276237e-1", "9.50931752211239285495049505085657017713666088362080797501802e-1", "6.30802012130870062682945015081761863931067293013258955343778e-2", "6.22916032417338283997772198402041280406442608656027282971516e-2", "1.01234704888874738367295824940167643355513356779568705406784", "1.96944833555008294244986685532406298098072413044612704616322e-1", "1.99376521043298197844347518369444627078029826915592052885395e-1"}},
    {1919, -5, {"9.91626970449391190120065375691603307869168432425393027246461e-1", "9.66928542934465327687501727960259191399881824035838898518096e-1", "5.16250519391737985032758856394921007228280747268878440744985e-2", "5.11927938537353816441495037331388693220685650100201126875403e-2", "1.00830348246275834654768859589716815900017734037906681462563", "1.61510071182009635224873935048826307069473128169798810408497e-1", "1.62851167225628304445776509582425945288182157291019081292041e-1"}},
    {15, 2, {"9.91631350124208772416113128542931663285931294063429790320707e-1", "9.6694562166252637425279622904856894455713562353121900698931e-1", "5.16115491736098409485656502259201219221508814546575798901386e-2", "5.11796301890287181184593726440717802760518979266730770871608e-2", "1.00829917524547344978612091883472848581429991270008380063887", "1.6146817823629392564838873823359366811793493278535273069155e-1", "1.62808230944044271031125024384568087390406224942514678888855e-1"}},
    {123, -1, {"9.91836318069087705187124942727728357600132207036556462878924e-1", "9.67745160387997147798792684789342167232516025787429058117759e-1", "5.09756205748082575927660514685326080800166640609296304250187e-2", "5.05594718222046544128077173366523124606137026400005494244758e-2", "1.00809755636401562561836124615237890446220997948414504876256", "1.59494872669310888719416766211647036688709584726413224711449e-1", "1.60786391390522128979872081458598781283137208926674614804295e-1"}},
    {401, -2, {"9.94999905052264690312933241788360039234781133477662184049454e-1", "9.80149627829381253061088613630157405701051747960545392836919e-1", "3.98944166288077234878800147566889190716145032691861778441826e-2", "3.96949407577791744640266531969120990548925697360618224678441e-2", "1.00497521561104572335263319314978268509825429285632683633435", "1.25019830781877768766605963301827088642966175179403521750143e-1", "1.25641831395674061703476411438812397484588359965601604515276e-1"}},
    {2001, -1, {"9.99500124874960765236088476371764046655906090198756072437113e-1", "9.98001998750874641148953346374069437188094140749227873918167e-1", "1.261408653937546822437376210645289368559678219104918758597e-2", "1.26077810712893421840658378194801591191276822233752444655704e-2", "1.0004996253744620128707967347608408826907663509347042821248", "3.96184207064051960252537836441011523816637352723975686084681e-2", "3.96382150746862272858004434441442028144014740813117657071236e-2"}},
    {1, 40, {"9.9999999999954525264911343248346591124625109300799685238164e-1", "9.99999999998181010596454970704782475090753967540429128179298e-1", "3.80461006547430069376219150784702597310194748173457155609099e-7", "3.80461006547257055741376069941630630740728600295713630108153e-7", "1.00000000000045474735088636072138095049683018913956285365664", "1.19525350314651276196187927325561453683082899279006228759847e-6", "1.19525350314705630032607279235313993346755183013514178486721e-6"}},
    {1, 100, {"9.99999999999999999999999999999605569547389494097294135717359e-1", "9.99999999999999999999999999998422278189557976389176542869435e-1", "3.54331924158508717983503242207651246806245632716552155617215e-16", "3.54331924158508717983503242207511487505025440672056085699537e-16", "1.00000000000000000000000000000039443045261050590270586428264", "1.11316656986870676889356936314836502804926454295540123008198e-15", "1.11316656986870676889356936314880409484324874130851106555559e-15"}},
};
// clang-format on
const char* const names[7] = {"I1/I0", "I2/I0", "e^-x I0", "e^-x I1", "K1/K0", "e^x K0", "e^x K1"};

template <class T>
T parse(const char* text) {
  if constexpr (std::is_floating_point_v<T>)
    return static_cast<T>(std::strtold(text, nullptr));
  else
    return T(text);
}

template <class T>
T evaluate(int function, const T& x) {
  switch (function) {
    case 0:
      return bessel_i1_over_i0(x);
    case 1:
      return bessel_i2_over_i0(x);
    case 2:
      return bessel_i0_scaled(x);
    case 3:
      return bessel_i1_scaled(x);
    case 4:
      return bessel_k1_over_k0(x);
    case 5:
      return bessel_k0_scaled(x);
    default:
      return bessel_k1_scaled(x);
  }
}

/// Relative error in units of eps. A reference below the smallest normal number (I2/I0 = x^2/8 at
/// x = 2^-100 in float) is met when the result underflows as well.
template <class T>
double error_in_eps(const T& computed, const T& expected) {
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  if (abs(expected) < (std::numeric_limits<T>::min)())
    return abs(computed) <= (std::numeric_limits<T>::min)() ? 0.0 : 1e30;
  return static_cast<double>(abs(computed - expected) / (abs(expected) * eps));
}

// Tolerances in units of eps. The arguments are exact, so only evaluation error counts.
// Built-in types, 4 eps: every branch returns a product or quotient of at most four quantities,
// each within one ulp: Boost's I_0, I_1, K_0, K_1 (computed in a wider type for float and double),
// exp, sqrt, and 1 + tail of a Hankel series whose tail, O(1/x), carries its rounding error only at
// that size. Measured maximum over 1482 arguments: 2.3 eps (docs/special-functions.md).
template <class T>
double tolerance(const T&) {
  return 4;
}
// cpp_bin_float_50 below x_T = 60, 48 eps: Boost has no rational approximations beyond 113 bits
// and falls back to series and continued fractions; their error, with cpp_bin_float_50's exp, was
// measured at up to 27 eps over 580 arguments below x_T (docs/special-functions.md). Beyond x_T the
// Hankel series are ours, 4 eps as above.
double tolerance(const Mp50& x) {
  return x < viscoroll::detail::bessel_asymptotic_threshold<Mp50>() ? 48 : 4;
}

template <class T>
void check_references() {
  using std::ldexp;
  for (const auto& r : references) {
    const T x = ldexp(T(r.m), r.e);
    for (int f = 0; f < 7; ++f) {
      if (f >= 4 && x == 0) continue;
      const T expected = parse<T>(r.value[f]);
      const T computed = evaluate(f, x);
      const double error = error_in_eps(computed, expected);
      INFO(names[f] << " at x = " << r.m << " * 2^" << r.e << ": computed "
                    << viscoroll::detail::format_value(computed) << ", expected " << r.value[f]
                    << ", error " << error << " eps");
      CHECK(error <= tolerance(x));
    }
  }
}

/// Both sides of a switch point t agree: |f(prior(t)) - f(t)| is within the sum of the two sides'
/// tolerances; the functions themselves change by less than eps over one ulp of x there
/// (|x f'/f| <= 1 for all seven).
template <class T>
void check_continuity(const T& threshold) {
  using std::abs;
  const T below = boost::math::float_prior(threshold);
  const double allowed = tolerance(below) + tolerance(threshold);
  for (int f = 0; f < 7; ++f) {
    if (f >= 4 && below <= 0) continue;
    const T a = evaluate(f, below);
    const T b = evaluate(f, threshold);
    INFO(names[f] << " across x = " << viscoroll::detail::format_value(threshold) << ": "
                  << viscoroll::detail::format_value(a) << " vs "
                  << viscoroll::detail::format_value(b));
    CHECK(abs(a - b) <= T(allowed) * std::numeric_limits<T>::epsilon() * abs(b));
  }
}

}  // namespace

TEMPLATE_TEST_CASE("Bessel ratios and scaled functions match 60-digit references",
                   "[special][bessel]", float, double, long double) {
  check_references<TestType>();
}

TEST_CASE("Bessel ratios and scaled functions match 60-digit references in cpp_bin_float_50",
          "[special][bessel][multiprecision]") {
  check_references<Mp50>();
}

TEMPLATE_TEST_CASE("Bessel functions are continuous across their switch points",
                   "[special][bessel]", float, double, long double, Mp50) {
  using T = TestType;
  using std::sqrt;
  SECTION("Hankel expansion threshold x_T") {
    check_continuity(viscoroll::detail::bessel_asymptotic_threshold<T>());
  }
  SECTION("I2/I0 series limit") {
    check_continuity(viscoroll::detail::bessel_i2_series_limit<T>());
  }
  SECTION("small-argument branches") {
    check_continuity(sqrt(std::numeric_limits<T>::epsilon()));
    check_continuity(std::numeric_limits<T>::epsilon());
  }
}

TEMPLATE_TEST_CASE("Bessel thresholds follow the precision", "[special][bessel]", float, double,
                   long double, Mp50) {
  // x_T = ceil(-ln(eps)/2) + 2 (docs/special-functions.md).
  const int expected = std::is_same_v<TestType, float>    ? 10
                       : std::is_same_v<TestType, double> ? 21
                       : std::is_same_v<TestType, Mp50>   ? 60
                                                          : 24;
  CHECK(viscoroll::detail::bessel_asymptotic_threshold<TestType>() == TestType(expected));
}

TEMPLATE_TEST_CASE("Bessel ratios have the right limits and never overflow", "[special][bessel]",
                   float, double, long double) {
  using T = TestType;
  using std::abs;
  using std::isfinite;
  using std::log;
  const T eps = std::numeric_limits<T>::epsilon();
  const T inf = std::numeric_limits<T>::infinity();

  SECTION("x = 0") {
    CHECK(bessel_i1_over_i0(T(0)) == 0);
    CHECK(bessel_i2_over_i0(T(0)) == 0);
    CHECK(bessel_i0_scaled(T(0)) == 1);
    CHECK(bessel_i1_scaled(T(0)) == 0);
  }
  SECTION("x = +inf") {
    CHECK(bessel_i1_over_i0(inf) == 1);
    CHECK(bessel_i2_over_i0(inf) == 1);
    CHECK(bessel_k1_over_k0(inf) == 1);
    CHECK(bessel_i0_scaled(inf) == 0);
    CHECK(bessel_i1_scaled(inf) == 0);
    CHECK(bessel_k0_scaled(inf) == 0);
    CHECK(bessel_k1_scaled(inf) == 0);
  }
  SECTION("large x up to 1e12 and beyond (DLMF 10.40.1-2, the next terms are below 1/(4x^3))") {
    for (T x : {T(1e7), T(1e12), T(1e30), (std::numeric_limits<T>::max)()}) {
      INFO("x = " << x);
      CHECK(abs(bessel_i1_over_i0(x) - (1 - 1 / (2 * x) - 1 / (8 * x * x))) <= 2 * eps);
      CHECK(abs(bessel_k1_over_k0(x) - (1 + 1 / (2 * x) - 1 / (8 * x * x))) <= 2 * eps);
      CHECK(abs(bessel_i2_over_i0(x) - (1 - 2 / x + 1 / (x * x))) <= 2 * eps);
      CHECK(isfinite(bessel_i0_scaled(x)));
      CHECK(isfinite(bessel_k1_scaled(x)));
    }
  }
  SECTION("tiny x: x/2, x^2/8 and 1/(x (-ln(x/2) - gamma)) (DLMF 10.25.2, 10.31.1-2)") {
    const T gamma = boost::math::constants::euler<T>();
    for (T x : {T(1e-30), T(1e-20), (std::numeric_limits<T>::min)()}) {
      INFO("x = " << x);
      CHECK(bessel_i1_over_i0(x) == x / 2);
      const T k_ratio = 1 / (x * (-log(x / 2) - gamma));
      CHECK(abs(bessel_k1_over_k0(x) - k_ratio) <= 2 * eps * k_ratio);
      CHECK(isfinite(bessel_k0_scaled(x)));
    }
    const T x = T(1e-15);
    CHECK(abs(bessel_i2_over_i0(x) - x * x / 8) <= 2 * eps * (x * x / 8));
  }
  SECTION("domain errors name the function and the argument") {
    CHECK_THROWS_AS(bessel_i1_over_i0(T(-1)), std::invalid_argument);
    CHECK_THROWS_AS(bessel_i2_over_i0(std::numeric_limits<T>::quiet_NaN()), std::invalid_argument);
    CHECK_THROWS_AS(bessel_i0_scaled(-inf), std::invalid_argument);
    CHECK_THROWS_AS(bessel_k1_over_k0(T(0)), std::invalid_argument);
    CHECK_THROWS_AS(bessel_k0_scaled(T(-2)), std::invalid_argument);
    CHECK_THROWS_WITH(bessel_k1_scaled(T(0)),
                      Catch::Contains("bessel_k1_scaled") && Catch::Contains("x > 0"));
  }
}

TEST_CASE("Bessel ratios in float reach arguments whose unscaled functions overflow",
          "[special][bessel]") {
  // I_0(100) ~ 1e42 and K_1(1e-40) ~ 1e40 exceed FLT_MAX; the ratios and scaled forms do not.
  CHECK(std::abs(bessel_i1_over_i0(100.0f) - 0.994987373f) <=
        4 * std::numeric_limits<float>::epsilon());
  const float k = bessel_k1_over_k0(1e-40f);
  CHECK(std::isfinite(k));
  CHECK(k > 1e38f);
}

TEST_CASE(
    "bessel_i1_over_i0_fast: double from its own interpolant, within 2.5 eps; other types "
    "forward",
    "[special]") {
  using viscoroll::special::bessel_i1_over_i0_fast;
  // Against the 60-digit references at every point of the table (they straddle x_T = 21 and the
  // sqrt(eps) branch), and against cpp_bin_float_50 on a geometric grid of 696 points in
  // [1.5e-8, 21) and at both sides of every piece boundary k/2, where the piecewise Chebyshev
  // interpolant is used (detail/i1_over_i0_chebyshev.hpp). Bound 2.5 eps: half an ulp for the
  // coefficients' rounding and for each of the four levels of Estrin's sum (its later terms are
  // below 1/7 of the leading one), the truncation below 1e-17; measured 1.79 eps over 27,000
  // points of the range (docs/special-functions.md).
  for (const auto& r : references) {
    const double x = std::ldexp(double(r.m), r.e);
    const double expected = parse<double>(r.value[0]);
    INFO("x = " << r.m << " * 2^" << r.e);
    CHECK(error_in_eps(bessel_i1_over_i0_fast(x), expected) <= 2.5);
  }
  double worst = 0;
  for (double x = 1.5e-8; x < 21; x *= 1.0307) {  // 696 points
    const Mp50 big(x);
    const Mp50 exact =
        boost::math::cyl_bessel_i(Mp50(1), big) / boost::math::cyl_bessel_i(Mp50(0), big);
    const double error =
        static_cast<double>(abs((Mp50(bessel_i1_over_i0_fast(x)) - exact) / exact) /
                            std::numeric_limits<double>::epsilon());
    worst = std::max(worst, error);
  }
  for (int k = 1; k < 42; ++k) {  // both sides of each piece boundary
    for (const double x : {std::nextafter(k * 0.5, 0.0), k * 0.5}) {
      const Mp50 big(x);
      const Mp50 exact =
          boost::math::cyl_bessel_i(Mp50(1), big) / boost::math::cyl_bessel_i(Mp50(0), big);
      worst = std::max(worst,
                       static_cast<double>(abs((Mp50(bessel_i1_over_i0_fast(x)) - exact) / exact) /
                                           std::numeric_limits<double>::epsilon()));
    }
  }
  CHECK(worst <= 2.5);
  // From x_T = 21 on: the series in 1/x (detail::i1_over_i0_series) against the 50-digit ratio
  // (Hankel's two sums in cpp_bin_float_50 from its own x_T = 60, Boost below) on a geometric grid
  // of [21, 1e9]. Bound 1 eps: eps/2 for 1 + tail, eps/16 of truncation, and the tail's rounding
  // (a few eps of |tail| <= 1/40); measured 0.29 eps.
  worst = 0;
  for (double x = 21; x < 1e9; x *= 1.003) {  // 6904 points
    const Mp50 exact = viscoroll::special::bessel_i1_over_i0(Mp50(x));
    worst =
        std::max(worst, static_cast<double>(abs((Mp50(bessel_i1_over_i0_fast(x)) - exact) / exact) /
                                            std::numeric_limits<double>::epsilon()));
  }
  CHECK(worst <= 1);
  CHECK(bessel_i1_over_i0_fast(std::numeric_limits<double>::infinity()) == 1);
  // float and long double: the accurate function itself.
  for (const float x : {1e-3f, 0.5f, 3.0f, 9.5f, 40.0f})
    CHECK(bessel_i1_over_i0_fast(x) == bessel_i1_over_i0(x));
  for (const long double x : {1e-3L, 0.5L, 3.0L, 23.0L, 40.0L})
    CHECK(bessel_i1_over_i0_fast(x) == bessel_i1_over_i0(x));
}

TEST_CASE(
    "bessel_i2_over_i0_fast: within 2.5 eps of the 50-digit ratio; below 4 and in other "
    "types the accurate function",
    "[special]") {
  using viscoroll::special::bessel_i2_over_i0;
  using viscoroll::special::bessel_i2_over_i0_fast;
  // From x = 4 on, 1 - 2 r/x with r = bessel_i1_over_i0_fast(x) (within 1.79 eps, measured in the
  // test above): the subtraction amplifies r's error by (1 - I2/I0)/(I2/I0) <= 0.76 (at x = 4),
  // and adds the rounding of 2 r/x and of the difference, half an ulp each: at most 2.5 eps.
  // Against I2/I0 = 1 - 2 (I1/I0)/x in cpp_bin_float_50 (I1/I0 from Boost below 21, from
  // Hankel's sums above, as in the test above) on a geometric grid of [4, 1e6].
  double worst = 0;
  for (double x = 4; x < 1e6; x *= 1.01) {  // 1250 points
    const Mp50 big(x);
    const Mp50 ratio = x < 21 ? Mp50(boost::math::cyl_bessel_i(Mp50(1), big) /
                                     boost::math::cyl_bessel_i(Mp50(0), big))
                              : viscoroll::special::bessel_i1_over_i0(big);
    const Mp50 exact = 1 - 2 * ratio / big;
    worst =
        std::max(worst, static_cast<double>(abs((Mp50(bessel_i2_over_i0_fast(x)) - exact) / exact) /
                                            std::numeric_limits<double>::epsilon()));
  }
  INFO("worst error " << worst << " eps");
  CHECK(worst <= 2.5);
  for (const double x : {0.0, 1e-3, 0.5, 3.0, std::nextafter(4.0, 0.0)})
    CHECK(bessel_i2_over_i0_fast(x) == bessel_i2_over_i0(x));
  CHECK(bessel_i2_over_i0_fast(std::numeric_limits<double>::infinity()) == 1);
  for (const float x : {1e-3f, 3.0f, 9.5f, 40.0f})
    CHECK(bessel_i2_over_i0_fast(x) == bessel_i2_over_i0(x));
  for (const long double x : {1e-3L, 3.0L, 23.0L, 40.0L})
    CHECK(bessel_i2_over_i0_fast(x) == bessel_i2_over_i0(x));
}

TEST_CASE("bessel_i1_over_i0_fast: the interpolant's table", "[special]") {
  // detail::kI1OverI0Pieces recomputed as its header says: on piece k the interpolant of
  // r = I1/I0 (of r/x in z = x^2 on piece 0) at the 14 Chebyshev points of the first kind, its
  // Chebyshev coefficients by the discrete cosine sum, its monomial coefficients in u by
  // T_{j+1} = 2 u T_j - T_{j-1}, all in cpp_bin_float_50, each rounded once to double: every
  // entry equals the table's.
  using viscoroll::detail::kI1OverI0Pieces;
  constexpr int n = 14;
  const int pieces = static_cast<int>(std::size(kI1OverI0Pieces));
  CHECK(pieces == 2 * viscoroll::detail::bessel_asymptotic_threshold<double>());
  const Mp50 pi = boost::math::constants::pi<Mp50>();
  for (int k = 0; k < pieces; ++k) {
    Mp50 f[n], cheb[n], t_prev[n], t_cur[n], mono[n];
    for (int i = 0; i < n; ++i) {
      const Mp50 u = cos(pi * (i + Mp50(0.5)) / n);
      const Mp50 x = k == 0 ? Mp50(sqrt((u + 1) / 8)) : Mp50((k + (u + 1) / 2) / 2);
      const Mp50 r = boost::math::cyl_bessel_i(Mp50(1), x) / boost::math::cyl_bessel_i(Mp50(0), x);
      f[i] = k == 0 ? Mp50(r / x) : r;
    }
    for (int j = 0; j < n; ++j) {
      Mp50 sum = 0;
      for (int i = 0; i < n; ++i) sum += f[i] * cos(pi * j * (i + Mp50(0.5)) / n);
      cheb[j] = sum * (j == 0 ? 1 : 2) / n;
      t_prev[j] = j == 0 ? 1 : 0;
      t_cur[j] = j == 1 ? 1 : 0;
      mono[j] = (j == 0 ? cheb[0] : Mp50(0)) + cheb[1] * t_cur[j];
    }
    for (int j = 2; j < n; ++j) {
      Mp50 t_next[n];
      for (int m = 0; m < n; ++m)
        t_next[m] = (m > 0 ? Mp50(2 * t_cur[m - 1]) : Mp50(0)) - t_prev[m];
      for (int m = 0; m < n; ++m) {
        t_prev[m] = t_cur[m];
        t_cur[m] = t_next[m];
        mono[m] += cheb[j] * t_cur[m];
      }
    }
    for (int m = 0; m < n; ++m) {
      INFO("piece " << k << ", coefficient " << m);
      CHECK(static_cast<double>(mono[m]) == kI1OverI0Pieces[k][m]);
    }
  }
}

TEST_CASE("bessel_i1_over_i0_fast: the ratio's series in 1/x, its coefficients and length",
          "[special]") {
  // r_k of I1/I0 ~ sum r_k x^-k: the quotient of Hankel's sums (DLMF 10.40.1, a_k of 10.17.1),
  // r_0 = 1, r_k = c_k(1) - sum_{j=1..k} c_j(0) r_{k-j}, c_k(nu) = (-1)^k a_k(nu), recomputed here
  // in 50 digits: each table entry is the 50-digit value rounded to double.
  using viscoroll::detail::kI1OverI0Series;
  constexpr int n = static_cast<int>(std::size(kI1OverI0Series));
  std::vector<Mp50> c0(n), c1(n), r(n);
  c0[0] = c1[0] = 1;
  for (int k = 1; k < n; ++k) {
    const int odd = (2 * k - 1) * (2 * k - 1);
    c0[k] = -c0[k - 1] * Mp50(0 - odd) / Mp50(8 * k);
    c1[k] = -c1[k - 1] * Mp50(4 - odd) / Mp50(8 * k);
  }
  for (int k = 0; k < n; ++k) {
    r[k] = c1[k];
    for (int j = 1; j <= k; ++j) r[k] -= c0[j] * r[k - j];
    INFO("k = " << k);
    CHECK(static_cast<double>(r[k]) == kI1OverI0Series[k]);
  }
  CHECK(kI1OverI0Series[1] == -0.5);
  CHECK(kI1OverI0Series[4] == -25.0 / 128);
  // The tiers' lengths: at each tier's smallest x the first omitted term is below eps/16 and the
  // terms kept fall monotonically (the asymptotic series is used before its smallest term).
  const double eps = std::numeric_limits<double>::epsilon();
  // The last tier starts where bessel_i1_over_i0_fast hands over to the series.
  CHECK(std::end(viscoroll::detail::kI1OverI0Tiers)[-1].x ==
        viscoroll::detail::bessel_asymptotic_threshold<double>());
  for (const auto& t : viscoroll::detail::kI1OverI0Tiers) {
    INFO("x = " << t.x << ", " << t.terms << " terms");
    // The 25th term (k = 25) is not in the table: it is r_25 = c_25(1) - sum c_j(0) r_{25-j}.
    Mp50 next;
    if (t.terms < n) {
      next = r[t.terms];
    } else {
      const int odd = (2 * n - 1) * (2 * n - 1);
      const Mp50 c0n = -c0[n - 1] * Mp50(0 - odd) / Mp50(8 * n);
      const Mp50 c1n = -c1[n - 1] * Mp50(4 - odd) / Mp50(8 * n);
      next = c1n;
      for (int j = 1; j < n; ++j) next -= c0[j] * r[n - j];
      next -= c0n * r[0];
    }
    CHECK(static_cast<double>(abs(next) / pow(Mp50(t.x), t.terms)) < eps / 16);
    for (int k = 2; k <= t.terms; ++k) {
      const Mp50 term_k = k < n ? abs(r[k]) : abs(next);
      CHECK(term_k / Mp50(t.x) <= abs(r[k - 1]));
    }
  }
}

}  // namespace test_bessel_ratio
