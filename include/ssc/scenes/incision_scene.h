#ifndef ssc_scenes_incision_scene_h
#define ssc_scenes_incision_scene_h

#include <vector>

#include <ssc/scenes/scene.h>
#include <ssc/scenes/wound.h>

namespace ssc
{
  /**
   * An incision of the pre-tensioned skin (section "Incision"): a straight
   * cut through the patch centre, down through the top layers, made once
   * along x and once along y on otherwise identical models. The skin's
   * pre-tension (Layer stack/<layer>/Prestretch, held by the patch's
   * sides) comes on in load steps with the cut already made, which for an
   * elastic body is the same end state as cutting the tensed skin; the
   * wound it opens is measured after each step (WoundShape). Where the
   * skin's law has Langer's lines (Gasser-Ogden-Holzapfel), each cut is
   * named along or across them, and the ratio of their gaps is reported.
   * With Incision/Shape = disc, a disc of the top layers is excised instead
   * (one model): the wound's area change, aspect ratio and orientation,
   * and the area change of the freed disc ("disc"). With Shape = ellipse,
   * an ellipse is excised with its long axis along x and along y (two
   * models); with Incision/Closure/Suture spacing > 0, sutures
   * (SutureTies, find_sutures()) then draw the opened wound's lips
   * together in load steps: each suture's force, the skin's largest
   * stress and the dog ears' height (ClosureState, "closure").
   *
   * Writes into output/<run name>/: summary.json (keys "wound", "disc",
   * "closure"), wound.csv (per cut and step), wound_lips.csv (the lips'
   * outlines at full pre-tension), closure.csv (per ellipse and suture
   * step), volume.pvd (the models at the end, steps 1 and 2: closed where
   * sutured), parameters.prm, log.txt. WoundRecord keeps the tables and
   * the summary.
   */
  class IncisionScene : public Scene
  {
  public:
    using Scene::Scene;

    /// The wounds of the cuts along x and along y (or of the excision) at
    /// full pre-tension.
    std::vector<WoundShape>
    run();
  };
} // namespace ssc

#endif
