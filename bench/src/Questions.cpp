#include "lpv/bench/Questions.h"

namespace lpv::bench {

const std::vector<Question>& reportQuestions() {
    static const std::vector<Question> questions = {
        {"steps", "lpv.propagationSteps=0,1,2,4,8,16,32,64", "lpv.propagationSteps=0,4,16"},
        {"grid", "lpv.gridSize=16,32,64", "lpv.gridSize=16,32"},
        // The fitted cell size (issue #41) against fixed ones, in metres as the report's scenes are.
        {"cellSize", "lpv.cellSize=auto,0.0625,0.125,0.25,0.5,1", "lpv.cellSize=auto,0.25"},
        {"cascades", "lpv.cascades=1,2,3,4", ""},
        // Convergence (issue #47): on top of the fitted LPV, cells 2h, h,
        // h/2 with half, as many and twice the cells per axis and steps, so
        // the cascades cover the same space and light travels as far
        // (LpvFit.h). x4 (4 cascades of 128^3) needs a 384 MiB storage
        // buffer, over the 128 MiB GL_MAX_SHADER_STORAGE_BLOCK_SIZE of
        // llvmpipe: the render refuses it. Not in --quick: x2 alone costs
        // 13x the fitted frame.
        {"convergence", "lpv.refinement=0.5,1,2", ""},
        // Three SH bands against two (issue #47) at the project's settings
        // (three run in the compute gather; docs/lpv.md, "Three bands").
        {"bands", "lpv.shBands=2,3", ""},
        {"rsm", "rsm.tileSize=64,128,256,512,1024", ""},
        {"variant", "lpv.variant=computeGather,computeScatter,rasterGather,rasterScatter", ""},
        {"occlusion", "lpv.occlusion=false,true", "lpv.occlusion=false,true"},
        {"directed", "lpv.directedPropagation=off,on", ""},
        {"sky", "effects.skyInjection=off,on", ""},
        {"subsurface", "effects.subsurface=off,on", ""},
        {"glossy", "effects.glossyReflections=off,on", ""},
        {"bounces", "lpv.bounces=1,2,3", ""},
        {"viewShift", "lpv.viewShift=0,0.5,0.75,1", ""},
        {"damping", "lpv.bleedingDamping=0,1,2,4", ""},
        {"offset", "lpv.injectionOffset=0,0.5,0.875,1,2", ""},
        {"firstStep", "lpv.occlusionFirstStep=true,false", ""},
        {"strength", "lpv.occlusionStrength=0.5,1,1.333,2", ""},
        {"lookupOffset", "lpv.lookupOffset=0,0.25,0.5,1", ""},
        {"visibility", "lpv.visibilityLookup=false,true", ""},
        {"clampToScene", "lpv.clampToScene=false,true", ""},
        {"twoSided", "lpv.twoSidedOcclusion=false,true", ""},
        {"geometrySource", "lpv.geometrySource=views,scene", ""},
    };
    return questions;
}

} // namespace lpv::bench
