# Every course scene whose files are present, with its official image and criterion
# (the thresholds are in reference_check.cpp). hw1's reference/ images were rendered
# with back-face culling, reference_nobfc/ and hw2 without.
foreach(s simple spheres spheres_mirror two_spheres cornellbox cornellbox_recursive bunny
          scienceTree scienceTree_glass)
  rt_reference(hw1.${s} hw1/${s}.xml hw1/reference/${s}.png hw12 --cull-back-faces)
endforeach()
foreach(s scienceTree scienceTree_glass)
  rt_reference(hw1_nobfc.${s} hw1/${s}.xml hw1/reference_nobfc/${s}.png hw12)
endforeach()
foreach(pair berserker_smooth:berserker_smooth low_poly_smooth:low_poly_scene_smooth
             ton_Roosendaal_smooth:ton_Roosendaal_smooth tower_smooth:tower_smooth
             windmill_smooth:windmill_smooth trex_smooth:trex_smooth)
  string(REPLACE ":" ";" p ${pair})
  list(GET p 0 xml)
  list(GET p 1 png)
  rt_reference(hw1.${xml} hw1/akif_uslu/${xml}.xml hw1/reference/akif_uslu/${png}.png hw12
               --cull-back-faces)
endforeach()
rt_reference(hw1.car_smooth hw1/akif_uslu/car_smooth_fixed.xml
             hw1/reference/akif_uslu/Car_smooth.png hw12 --cull-back-faces --camera 0)
rt_reference(hw1.car_front_smooth hw1/akif_uslu/car_smooth_fixed.xml
             hw1/reference/akif_uslu/Car_front_smooth.png hw12 --cull-back-faces --camera 1)
foreach(s simple_transform spheres ellipsoids metal_glass_plates)
  rt_reference(hw2.${s} hw2/${s}.xml hw2/reference/${s}.png hw12)
endforeach()
rt_reference(hw2.grass_desert hw2/grass/grass_desert.xml hw2/reference/grass/grass_desert.png hw12)
rt_reference(hw2.two_berserkers hw2/akif_uslu/berserker/two_berserkers.xml
             hw2/reference/akif_uslu/two_berserkers.png hw12)
# cornellbox_boxes_dynamic puts its camera behind the box's front wall, which only
# back-face culling of camera rays removes.
foreach(s cornellbox_area cornellbox_brushed_metal metal_glass_plates spheres_dof)
  rt_reference(hw3.${s} hw3/${s}.xml hw3/reference/${s}.png hw3)
endforeach()
rt_reference(hw3.cornellbox_boxes_dynamic hw3/cornellbox_boxes_dynamic.xml
             hw3/reference/cornellbox_boxes_dynamic.png hw3 --cull-back-faces)
foreach(s cornellbox_area cornellbox_brushed_metal ellipsoids metal_glass_plates simple_transform
          spheres_dof)
  rt_reference(spring2021.${s} hw3_extra/spring2021/${s}.xml
               hw3_extra/spring2021/reference/${s}.png hw3)
endforeach()
rt_reference(spring2021.cornellbox_boxes_dynamic hw3_extra/spring2021/cornellbox_boxes_dynamic.xml
             hw3_extra/spring2021/reference/cornellbox_boxes_dynamic.png hw3 --cull-back-faces)
