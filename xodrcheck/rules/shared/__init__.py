"""What the rule families share and no family owns: the context a rule reads (:mod:`.context`), lane lines sampled
once per file (:mod:`.sampled`, :mod:`.grids`), road ends and their joints (:mod:`.road_ends`, :mod:`.link_joints`,
:mod:`.lane_joints`, :mod:`.lane_boundary`), junction shapes (:mod:`.junction_shapes`), where a finding is
(:mod:`.places`), the Annex F UIDs the rules enforce (``*_uids``) and the rule help's text (:mod:`.docformat`,
:mod:`.plaintext`)."""
