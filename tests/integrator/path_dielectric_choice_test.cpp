// --dielectric choose in the path tracer (cl/integrator/path.h, ContinuePath): a path that
// meets glass follows one of its rays, picked with the Fresnel probability, instead of
// splitting into both. Either way the pixel's expectation is the same; the estimates differ
// (one ray a bounce is noisier), so the choice is taken and unbiased
// (support/pixel_estimate.h: 4.5 standard errors).
#include <gtest/gtest.h>

#include "support/pixel_estimate.h"

namespace {

// One pixel seeing a glass sphere in front of a lit diffuse wall, path traced with
// next-event estimation: through the glass, paths meet it two or more times.
const char* const kGlass = R"(<Scene>
    <MaxRecursionDepth>6</MaxRecursionDepth>
    <BackgroundColor>0 0 0</BackgroundColor>
    <ShadowRayEpsilon>1e-4</ShadowRayEpsilon>
    <Cameras>
        <Camera id="1">
            <Position>0 0 3</Position> <Gaze>0 0 -1</Gaze> <Up>0 1 0</Up>
            <NearPlane>-0.1 0.1 -0.1 0.1</NearPlane> <NearDistance>1</NearDistance>
            <ImageResolution>1 1</ImageResolution> <NumSamples>40000</NumSamples>
            <ImageName>glass.exr</ImageName>
            <Renderer>PathTracing</Renderer>
            <RendererParams>NextEventEstimation</RendererParams>
        </Camera>
    </Cameras>
    <Lights>
        <PointLight id="1"> <Position>1 1 2</Position> <Intensity>2000 2000 2000</Intensity> </PointLight>
    </Lights>
    <Materials>
        <Material id="1">
            <AmbientReflectance>0 0 0</AmbientReflectance>
            <DiffuseReflectance>0.8 0.8 0.8</DiffuseReflectance>
            <SpecularReflectance>0 0 0</SpecularReflectance> <PhongExponent>1</PhongExponent>
        </Material>
        <Material id="2" type="dielectric">
            <AmbientReflectance>0 0 0</AmbientReflectance>
            <DiffuseReflectance>0 0 0</DiffuseReflectance>
            <SpecularReflectance>0 0 0</SpecularReflectance> <PhongExponent>1</PhongExponent>
            <AbsorptionCoefficient>0 0 0</AbsorptionCoefficient>
            <RefractionIndex>1.5</RefractionIndex>
        </Material>
    </Materials>
    <VertexData>
        -5 -5 -1.5  5 -5 -1.5  5 5 -1.5  -5 5 -1.5  0.1 0 0
    </VertexData>
    <Objects>
        <Mesh id="1"> <Material>1</Material> <Faces>1 2 3 1 3 4</Faces> </Mesh>
        <Sphere id="1"> <Material>2</Material> <Center>5</Center> <Radius>0.8</Radius> </Sphere>
    </Objects>
</Scene>)";

TEST(PathDielectricChoice, ChooseFollowsOneRayWithTheSameExpectation) {
  const rt::SceneDesc scene = rt::load_scene_text(kGlass, "glass.xml");
  rt::RenderOptions split, choose;
  choose.fresnel_choice = true;
  const rt::test::PixelStats a = rt::test::RenderOnePixel(scene, split);
  const rt::test::PixelStats b = rt::test::RenderOnePixel(scene, choose);
  ASSERT_GT(a.mean, 1.0) << "the pixel sees light through the glass";
  EXPECT_NE(a.mean, b.mean) << "--dielectric choose renders as split";
  // Splitting averages both rays at each glass hit; one chosen ray has the same mean and
  // a larger variance.
  EXPECT_GT(b.standard_error, a.standard_error);
  rt::test::ExpectSameMean(a, b, "split vs choose");
}

}  // namespace
