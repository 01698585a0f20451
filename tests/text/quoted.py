"""Real collision narratives quoted by the extraction tests, one place for all of them: report id -> (source,
narrative), the narrative as the studyable set gives it (tests/text/csvr/study2.jsonl, tests/text/sgo/study3.jsonl,
tests/text/sgo4/study4.jsonl, tests/text/sgo5/study5.jsonl, tests/text/sgo6/study6.jsonl (its W half),
../shared/data/reports/dev.jsonl with the dev gold) and its source beside it; `test_quoted` holds them to the
studyable sets, word for word."""

from __future__ import annotations

from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.extractor import extract

from .invariance import content

QUOTED: dict[str, tuple[str, str]] = {
    'nhtsa-sgo-ads-30270-10184-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10184'
        ', version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On March [XXX], 2025 at 11:52 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Tempe, Arizon'
        'a was in a collision involving a passenger car in a parking lot at [XXX]. The Waymo AV was exiting a'
        ' parking lot at [XXX] when it slowed to a stop to yield for pedestrians entering the crosswalk ahead'
        '. As the Waymo AV remained stopped, a passenger car directly behind the Waymo AV approached the Waym'
        'o AV from behind, and the front of the passenger car made contact with the rear of the Waymo AV. The'
        ' passenger car continued to proceed straight, nudging the Waymo AV forward as the front of the passe'
        'nger car continued to make contact with the rear of the Waymo AV. The passenger car then passed the '
        'Waymo AV on the left and proceeded to exit the parking lot just after the pedestrians had finished c'
        'rossing. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both v'
        'ehicles sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Orde'
        'r 2021-01 because a vulnerable road user influenced the driving task of a vehicle involved. Waymo ma'
        'y supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30531-5336-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30531-5336,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On March [XXX], 2023 at 1:35 PM PST a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Ariz'
        'ona was in a collision involving a passenger car on [XXX] and [XXX]. While attempting a right turn i'
        'n autonomous mode from westbound [XXX] onto northbound [XXX], the Waymo AV was yielding to traffic a'
        'pproaching from the left. As the Waymo AV attempted to proceed, the test driver transitioned to manu'
        'al mode and brought the Waymo AV to a stop. A passenger car behind the Waymo AV proceeded forward an'
        "d made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
        'was not engaged and a test driver was operating the Waymo AV in manual mode. The Waymo AV and the pa'
        'ssenger vehicle sustained damage. Transdev Alternative Services is reporting this crash under Reques'
        't no. 2 of Standing General Order 2021-01. Transdev may supplement or correct its reporting with add'
        'itional information as it may become available. This is a duplicate of 30270-5326-1.'),
    'nhtsa-sgo-ads-30270-5591-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-5591,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2023 at 8:02 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, Arizo'
        'na was in a collision involving a van on [XXX] at [XXX]. The Waymo AV was traveling northbound on [X'
        'XX] in the leftmost lane as it was approaching the intersection with [XXX]. The signal for traffic p'
        'roceeding north on [XXX] was yellow as the Waymo AV approached the intersection. The Waymo AV slowed'
        ', preparing to stop, and a van traveling directly behind the Waymo AV then made contact with the rea'
        'r of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mo'
        'de. Both the Waymo AV and the van sustained damage. Waymo is reporting this crash under Request No. '
        '2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional i'
        'nformation as it may become available.'),
    'nhtsa-sgo-ads-30270-7882-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7882, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 12:41 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, Califor'
        'nia was in a collision involving a heavy truck on [XXX] near [XXX]. The Waymo AV was traveling north on [XXX] '
        'and came to a stop in its lane at the intersection with [XXX] as a heavy truck was making a left turn from wes'
        'tbound [XXX] onto southbound [XXX] in front of the Waymo AV. As the truck turned left, it partially crossed th'
        'e centerline of [XXX] and the left side of the truck body made contact with the driver side front corner of th'
        "e Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV"
        ' sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because'
        ' a vehicle involved was towed away. Waymo may supplement or correct its reporting with additional information '
        'as it may become available.'),
    'nhtsa-sgo-ads-30270-7938-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7938, version 1, column'
        ' "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May 28, 2024, Waymo received notice of an allegation that a Waymo Autonomous Vehicle ("Waymo AV") operating'
        ' in San Francisco, California may have contributed to a low-speed collision between a fire engine and an SUV o'
        'n [XXX] near [XXX]. On May [XXX], 2024 at 6:11 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was traveling north on [XXX] within its lane when it slowed to a stop as a fire engine, '
        'which was not displaying lights or sounding its sirens, approached in the oncoming direction. The Waymo AV beg'
        'an to slowly proceed straight within its lane as the fire engine was passing on its left. Neither the SUV nor '
        'the fire engine made contact with the Waymo AV. Waymo received notice of an allegation that as the fire engine'
        ' proceeded straight, it made contact with the driver side of an SUV that was parked at the curb immediately to'
        " the right of the fire engine. When the Waymo AV proceeded in its lane past the fire engine, the Waymo AV's Le"
        'vel 4 ADS was engaged in autonomous mode. Waymo is reporting this crash under Request No. 2 of Standing Genera'
        'l Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may become av'
        'ailable.'),
    'nhtsa-sgo-ads-30270-6662-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-6662, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On October [XXX], 2023 at 5:42 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, Califor'
        'nia was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV came to a stop in the rightmo'
        'st travel lane heading south on [XXX] at [XXX], behind a van that was unloading passengers and cargo in the tr'
        'avel lane. As the Waymo AV was awaiting an opportunity to maneuver into the left lane to pass the van, the pas'
        'senger car behind the Waymo AV maneuvered into the left lane to pass both vehicles. As the passenger car passe'
        'd the Waymo AV, the drivers side of the passenger car made contact with the rear left corner of the Waymo AV. '
        'At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained d'
        'amage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01.'),
    'nhtsa-sgo-ads-30270-8875-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8875, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On September [XXX], 2024 at 6:17 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, Calif'
        'ornia was in a collision involving a van on [XXX] near [XXX]. The Waymo AV was stopped in traffic in the dedic'
        'ated right turn lane of southwestbound [XXX]. While the Wamo AV remained stopped, a van traveling behind the W'
        'aymo AV partially entered the left adjacent lane to maneuver around the Waymo AV. As the van was passing the s'
        'topped Waymo AV, the front passenger side of the van made contact with the rear driver side of the Waymo AV. A'
        't the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The van sustained damage. '
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or c'
        'orrect its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9823-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9823, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 12:38 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Arizona was '
        'in a collision involving a remote controlled toy car on [XXX]. The Waymo AV was traveling westbound on [XXX] w'
        'hen it approached a remote controlled toy car that was crossing the intersection of [XXX]. As the Waymo AV tra'
        'versed the intersection, the front of the Waymo AV made contact with the remote controlled toy car. At the tim'
        "e of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The remote controlled toy car sust"
        'ained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may s'
        'upplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9853-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9853, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 7:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, Calif'
        'ornia was in a collision involving a passenger car on [XXX] The Waymo AV was stopped at the curb facing southw'
        'est on [XXX] for a passenger pickup when a passenger car approached the Waymo AV from behind, and came to a st'
        'op. The passenger car then maneuvered to pass the Waymo AV on the left, and the passenger side of the passenge'
        'r car made contact with the rear driver side of the stationary Waymo AV. At the time of the impact, the Waymo '
        "AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash "
        'under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with addi'
        'tional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9910-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9910, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 1:23 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, Calif'
        'ornia was in a collision involving an SUV on [XXX]. The Waymo AV was traveling east on [XXX], then pulled over'
        ' at the curb for a passenger drop-off. The Waymo AV passenger opened the rear driver side door and was attempt'
        'ing to exit the Waymo AV. An SUV traveling east on [XXX] attempted to pass the Waymo AV on the left, and the p'
        'assenger side of the SUV made contact with the open back driver side door of the stationary Waymo AV. The pass'
        'engers in the Waymo AV were not belted at the time of the collision, likely because they were at a drop-off lo'
        "cation preparing to exit the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in au"
        'tonomous mode. The SUV sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General'
        ' Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may become ava'
        'ilable.'),
    'nhtsa-sgo-ads-30413-6684-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-6684, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The May vehicle was traveling eastbound on [XXX] in autonomy. The vehicles internal facing cameras show that t'
        'he operator started to fall asleep while applying physical input to the steering wheel. The road started to be'
        'nd to the left. The physical input from the operator was enough to deviate the vehicle from its intended path '
        'but not enough to trigger an intervention and take the vehicle out of autonomy. The vehicle, going straight as'
        ' the road curved, then struck the curb, resulting in minor vehicle damage. Due to the vehicle being off path, '
        'the vehicle begins to stop. This occurs as the operator wakes up. The operator was not injured and no third pa'
        'rties were impacted or otherwise affected by the incident. The local May Mobility site staff did not notice an'
        'y signs of fatigue from this operator prior to going out in the vehicle. The operator had responded to audio c'
        'heck-ins from site staff at a regular interval. We are exploring additional risk mitigation options for in-cab'
        'in health monitoring, in addition to the existing cameras and radio check-ins.'),
    'nhtsa-sgo-ads-30270-7012-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7012,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2023 at 7:02 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Tempe, Ariz'
        'ona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling south'
        'bound on [XXX] in the rightmost lane of three lanes in the southbound direction. After the Waymo AV '
        'crossed the intersection with [XXX], an SUV in the leftmost lane initiated a right lane change in fr'
        'ont of a passenger car in the middle lane. The passenger car in the middle lane then moved into the '
        'rightmost lane, and the passengers side of the passenger car made contact with the front drivers sid'
        'e of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mo'
        'de. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of Standing Ge'
        'neral Order 2021-01. Waymo may supplement or correct its reporting with additional information as it'
        ' may become available.'),
    'nhtsa-sgo-ads-30413-8861-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-8861,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A May autonomous vehicle was traveling in the right lane of a two-lane road, maintaining a steady sp'
        'eed of 30 mph, in compliance with the posted speed limit. The road was characterized by light traffi'
        'c, with a slight curvature that transitioned from a gentle rightward sway to a leftward sway. As the'
        ' vehicle navigated this transition of curvature, the May vehicle made contact with the curb, causing'
        ' a flat tire. At the time of the incident, no other vehicles or pedestrians were present in the imme'
        'diate vicinity, and there were no external factors such as obstructions or adverse weather condition'
        's influencing the vehicles path. Speed was reduced from 30mph to 25mph after this event and tested ('
        'and worked to mitigate the problem in that area) and now will be reduced to 22 which is the sweet sp'
        'ot for most areas on the route. The May vehicle chose to maneuver at the curb due to perceived risk '
        'from a car in an adjacent lane, so May is increasing the allowed distance to the curb to mitigate ho'
        'w close the vehicles are allowed to get.'),
    'nhtsa-sgo-ads-30270-8139-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8139, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 12:28 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], California '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling north on '
        '[XXX] through the intersection at [XXX] when a passenger car passed the Waymo AV on the right. The '
        'passenger car turned to the left in front of the Waymo AV and came to an abrupt stop. The driver side '
        'rear corner of the passenger car made contact with the passenger side front corner of the Waymo AV. At '
        'the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained'
        ' damage and the passenger car left the scene. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-7726-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7726, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2024 at 7:08 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, '
        'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was stopped in '
        'traffic for a red light on southbound [XXX]. The driver of a passenger car traveling directly behind the'
        ' Waymo AV began to exit their vehicle, and as they did so with the door open, the passenger car started '
        'to proceed straight and made contact with the rear of the Waymo AV. At the time of the impact, the Waymo'
        ' AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage and the passenger car '
        'left the scene. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'dmvca-waymo-20220206-r282': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 282, column '
        '"Accident Detail Description")',
        'On February 6, 2022 at 1:53 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Pine Street at Fillmore Street. The Waymo'
        ' AV was stopped in the right lane of a three lane, one-way street in manual mode while boarding a '
        'passenger. A passenger vehicle stopped behind the Waymo AV then attempted to go around the Waymo AV, '
        'attempting to merge with traffic in the center lane but colliding instead with a third passenger vehicle'
        ' and also making contact with the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was '
        'not engaged and a test driver was operating the Waymo AV in manual mode. The Waymo AV and the passenger '
        'vehicle that made contact with it sustained moderate damage. The third vehicle sustained minor damage. '
        'The Waymo AV passenger reported minor discomfort at the scene but advised they did not require medical '
        'attention.'),
    'csvr-waymo-20191018-s40': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "40, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode on the interchange from '
        'eastbound Alma Street merging onto southbound Oregon Expressway in Palo Alto when it was rear-ended. '
        'The Waymo AV was yielding to cross-traffic when a passenger vehicle made contact with the Waymo AV’s '
        'rear bumper at approximately 8 MPH. The Waymo AV sustained minor damage to the rear bumper, and the '
        'passenger vehicle sustained minor damage to its front bumper. There were no injuries reported at the '
        'scene; the Waymo test driver later reported dizziness but declined medical attention.'),
    'dmvca-cruise-20201024-r143': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 143, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was traveling westbound on 17th'
        ' Street at the intersection with Potrero St., when the Cruise AV was struck by a 2007 Subaru Outback '
        'that crossed the centerline while driving eastbound on 17th Street. Immediately before the incident, the'
        ' driver of the Cruise AV, seeing the oncoming vehicle crossing the centerline, disengaged from '
        'autonomous mode and brought the Cruise AV to a stop. The oncoming car made contact with the front driver'
        ' side quarter panel of the Cruise AV, causing damage. There were no injuries, but the police were '
        'called. The driver of the 2007 Subaru Outback left the scene before the police arrived.'),
    'dmvca-cruise-20211226-r264': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 264, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("Cruise AV"), operating in supervised autonomous mode, was traveling '
        'eastbound on Fulton Street in the leftmost lane between 14th Avenue and Park Presidio Boulevard. A '
        'Toyota Sienna traveling southbound on 14th Avenue made an unprotected left turn to merge onto '
        'eastbound Fulton Street. The Cruise AV braked prior to the Cruise AV operator disengaging the Cruise '
        'AV from autonomous mode. The Cruise AV operator continued to brake but, shortly thereafter, the '
        'Toyota Sienna made contact with the Cruise AV, damaging the front left fender of the Cruise AV. '
        'Police were not called to the scene and no injuries were reported.'),
    'nhtsa-sgo-ads-30270-10669-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10669, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:28 PM MST a Waymo Autonomous Vehicle ("Waymo AV") operating in Scottsdale, '
        'Arizona was in a collision involving a passenger car in a parking lot near [XXX]. The Waymo AV was '
        'traveling westbound in a parking lot near [XXX] when it stopped for a rider pick-up. While the Waymo AV '
        'remained parked with hazard lights activated, a passenger car in a parking spot to the left of the Waymo'
        ' AV reversed and the rear of the passenger car made contact with the driver side of the stationary Waymo'
        " AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles"
        ' sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8851-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8851,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On September [XXX], 2024 at 11:27 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Franc'
        'isco, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was tr'
        'aveling on northeastbound [XXX] in the rightmost portion of the drivable roadway, having maneuvered '
        'around a segment of the rightmost lane that was blocked off due to road work. When the traffic light'
        ' was green, the Waymo AV entered the intersection to prepare to make a right turn onto southeastboun'
        'd [XXX]. It then slowed to a stop, with its hazards on due to a change in the traffic light configur'
        'ation. While the Waymo AV remained stopped, a passenger car traveling behind the Waymo AV maneuvered'
        ' around the left side of the Waymo AV and made contact with the rear driver side of the Waymo AV. At'
        ' the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sust'
        'ained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. W'
        'aymo may supplement or correct its reporting with additional information as it may become available.'),
    'csvr-waymo-20220219-s135': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 135, column 'Accident Detail Description'), transcribed",
        'On February 19, 2022 at 7:45 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francis'
        'co, California was in a collision involving a passenger vehicle at the northbound merge lane on the '
        '100 block of Bayshore Boulevard. While attempting a merge onto northbound Bayshore Boulevard from so'
        'uthbound Bayshore Boulevard, the Waymo AV came to a stop to yield for approaching traffic on the rig'
        'ht. While stopped, a vehicle approached from behind and made contact with the rear bumper of the Way'
        'mo AV. The other vehicle left the scene without exchanging information. At the time of the impact, t'
        'he Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driv'
        'er’s seating position). The Waymo AV sustained minor damage.'),
    'csvr-waymo-20230629-s259': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 259, column 'Accident Detail Description'), transcribed",
        'On June 29, 2023 at 7:50 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, C'
        'A was in a collision involving a pickup truck on Jersey Street at Church Street. The Waymo AV was tr'
        'aveling eastbound on Jersey Street and stopped at a stop sign at the intersection of Church Street. '
        'While yielding to pedestrians crossing the street, a pickup truck traveling directly behind the Waym'
        'o AV made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 A'
        'DS was engaged in autonomous mode. The Waymo AV sustained damage.'),
    'csvr-argo-20211019-s102': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "102, column 'Accident Detail Description'), transcribed",
        'An Argo AI Autonomous Vehicle (“Argo AV”) was involved in a rear-end collision on Grant Ave. The Argo '
        'AV came to a complete stop at the stop sign located at the intersection of Grant Ave. and El Camino '
        'Real. After the Argo AV began to initiate a right-hand turn, the Argo AV came to a stop in response to '
        'oncoming traffic. A vehicle trailing behind the Argo AV moved forward and contacted the Argo AV’s left '
        'rear bumper. The Argo AV sustained minor damage to its left rear bumper.'),
    'csvr-cruise-20190524-s14': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "14, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was changing lanes into the '
        'left turn lane on eastbound Geary Boulevard between 8th and 9th Avenues when the Cruise AV slowed down. '
        'The driver of the Cruise AV disengaged from autonomous mode and, shortly thereafter, another vehicle '
        'changing into the same lane made contact with the rear bumper of the Cruise AV, damaging the Cruise '
        'AV’s bumper. There were no injuries and police were not called.'),
    'csvr-cruise-20200129-s50': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "50, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was traveling northwest bound '
        'on Columbus Street approaching the intersection with Jones Street when the Cruise AV slowed down. The '
        'driver of the Cruise AV disengaged from autonomous mode and, shortly thereafter, another vehicle, '
        'changing into the Cruise AV’s lane from the left adjacent lane, made contact with the rear bumper of '
        'the Cruise AV. There were no injuries reported at the scene by either party and police were not called. '
        'Both of the Cruise AV test operators later mentioned neck and shoulder pain.'),
    'csvr-cruise-20211211-s119': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "119, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in supervised autonomous mode, was at a complete '
        'stop in response to a red light on northbound Larkin Street at the intersection with Turk Street. The '
        'Cruise AV entered the intersection on a green light and continued straight when a cyclist traveling '
        'eastbound on Turk Street entered the crosswalk. The Cruise AV braked to the cyclist and, shortly '
        "thereafter, another vehicle traveling behind the Cruise AV made contact with the Cruise AV's rear "
        'bumper, damaging the rear left bumper. The driver of the other vehicle left the scene without '
        'exchanging information. There were no injuries and police were not called.'),
    'csvr-cruise-20220409-s148': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "148, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was stopped at a '
        'red light on northbound Van Ness Avenue at the intersection with Sacramento Street. The Cruise AV '
        'entered the intersection on a green light and continued straight through the intersection before '
        'braking and coming to a complete stop near the end of the intersection. At the same time, a Toyota '
        'Sedan on westbound Sacramento Street began was making an unprotected right turn on a red light onto '
        'northbound Van Ness Avenue behind the Cruise AV. Shortly thereafter, the Toyota Sedan rear-ended the '
        "Cruise AV and made contact with the Cruise AV's rear bumper, damaging the rear right bumper. The driver "
        'of the other vehicle left the scene without exchanging information. There were no injuries and a police '
        'report was later filed.'),
    'csvr-cruise-20220905-s189': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 189, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'eastbound on Sacramento Street between Van Ness Avenue and Polk Street. The Cruise AV approached a '
        'semi-trailer truck that was stopped in the left lane of traffic. The Cruise AV stopped before '
        'maneuvering into the bus and taxi lane to pass the semi-trailer truck. As the Cruise AV was slowly '
        'maneuvering around the semi-trailer truck and merging back into the left lane of traffic, a Honda '
        'Accord traveling behind the Cruise AV attempted to pass the Cruise AV and made contact with the '
        'Cruise AV, damaging the rear passenger side bumper of the Cruise AV. The driver of the Honda Accord '
        'left the scene without exchanging information. There were no reported injuries.'),
    'csvr-cruise-20230422-s236': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "236, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was at a complete '
        'stop in response to a red light on 10th Street at the intersection with Division Street. The Cruise AV '
        'began to make a right turn onto Division Street after the light turned green before yielding to a '
        'pedestrian in the crosswalk. Shortly thereafter, a silver Infiniti Sedan traveling behind the Cruise AV '
        'made contact with the Cruise AV’s rear bumper, causing damage to the Cruise AV’s rear fascia. The '
        'driver of the Infiniti Sedan left the scene without exchanging information. There were no reported '
        'injuries.'),
    'csvr-cruise-20230504-s240': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "240, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'northbound on Franklin Street between Clay Street and Sacramento Street. As the Cruise AV passed '
        'through the intersection with Sacramento Street, a scooterist approaching from the rear merged into the '
        "Cruise AV's lane behind the Cruise AV. The Cruise AV began to brake, and the scooterist made contact "
        'with the rear window and rear bumper of the Cruise AV. This caused damage to the rear window, rear '
        'bumper and driver side rear headlight of the Cruise AV. The parties exchanged information. There were '
        'no injuries reported at the scene and police were not called. The scooterist later reported injuries.'),
    'csvr-cruise-20230609-s250': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "250, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle (“Cruise AV”), operating in driverless autonomous mode, was traveling '
        'northbound on Harrison St. between 18th Street and 19th Street. As the Cruise AV was coming to a stop '
        'for a stop sign at the intersection with 18th Street, a van approaching from the rear failed to stop '
        "behind the Cruise AV and made contact with the Cruise AV's rear bumper, damaging the rear bumper of the "
        'Cruise AV. Police and Emergency Medical Services were called and the Cruise AV was towed from the '
        'scene. The driver of the van was transported by Emergency Medical Services for further evaluation.'),
    'csvr-cruise-20230615-s252': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "252, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'eastbound on Sacramento Street between Lyon Street and Baker Street. The Cruise AV approached a '
        'motorized articulating boom lift (“ABL”), which was stopped in the Cruise AV’s lane of travel. As the '
        'Cruise AV began to maneuver around and to the left of the ABL, the Cruise AV made contact with the arm '
        'of the ABL, which was elevated above the roadway. This caused damage to the Cruise AV’s roof Lidar '
        'assembly. There were no reported injuries.'),
    'csvr-cruise-20230721-s263': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "263, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'eastbound on McAllister Street between Van Ness Avenue and Polk Street. As the Cruise AV was slowing '
        'for a red light at the intersection with Polk Street, an Infiniti Q60 traveling westbound on McAllister '
        'Street failed to stop for the red light, entered the intersection, and made contact with a black sedan '
        'traveling southbound on Polk Street that entered the intersection on a green light. The Infiniti Q60 '
        'spun after contact and continued into the Cruise AV, damaging the front bumper fascia of the Cruise AV. '
        'The driver of the Infiniti Q60 was transported by police. There were no reported injuries and both the '
        'Infiniti Q60 and the black sedan were towed from the scene.'),
    'csvr-cruise-20230728-s266': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 266, column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'northbound on Van Ness Avenue between California Street and Sacramento Street. As the Cruise AV was '
        'passing through the intersection with Sacramento Street on a green light, a bag lying on the '
        'roadway blew in front of the Cruise AV. The Cruise AV braked for the object, and a white pickup '
        'truck traveling behind the Cruise AV rear-ended the Cruise AV, damaging the rear right bumper, rear '
        'right quarter panel, and rear windshield. The driver of the white pickup truck left the scene '
        'without exchanging information. There were no reported injuries and the Cruise AV was towed.'),
    'csvr-mercedes-benz-20220519-s161': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "161, column 'Accident Detail Description'), transcribed",
        'While departing from a standstill in heavy traffic with L3 ADS engaged, the subject Mercedes-Benz '
        'vehicle was struck in the rear bumper by a large semi-truck. No injuries were reported. The contact '
        'from the truck resulted in two minor scratches and two indentations on the rear bumper of the subject '
        'Mercedes-Benz. The driver of the truck did not pull over after the collision and departed the scene. '
        'After a police report was initiated, the subject Mercedes-Benz drove away from the incident location. '
        'Further inspection of the vehicle revealed no additional damage beyond the cosmetic dents and surface '
        'scratches on the Mercedes-Benz.'),
    'csvr-pony.ai-20220517-s159': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "159, column 'Accident Detail Description'), transcribed",
        'On May 17, 2022, a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous testing '
        'vehicle’s rear bumper. At the time of the collision, the Pony.ai vehicle was operating in autonomous '
        'mode with a safety operator in the driver’s seat and was moving at a low speed. The Pony.ai vehicle did '
        'not sustain any damage. There were no injuries or property damage, the police were not called to the '
        'scene, and a Pony.ai employee drove the Pony.ai vehicle back to Pony.ai’s Irvine facility.'),
    'csvr-waymo-20190206-s2': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 2, "
        "column 'Accident Detail Description'), transcribed",
        "Per the DMV's request of 02/21/2019, Waymo is resubmitting this OL316 so the DMV's digital version is "
        "compliant with accessibility requirements under AB 434. Waymo's original report was submitted on "
        '02/14/2019. A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode in the slip-lane from '
        'northbound Shoreline Boulevard to northbound Central Expressway in Mountain View when it was rear-ended. '
        'The Waymo AV was yielding to approaching traffic from the left when a passenger vehicle rear-ended the '
        'Waymo AV while travelling approximately 4 MPH. The Waymo AV sustained minor damage to the rear bumper, '
        'and the passenger vehicle had minor damage to its front bumper. No injuries were reported at the scene '
        'but the two operators in the Waymo AV later reported minor headache and neck soreness. They sought '
        'medical attention and both were cleared to return to work.'),
    'csvr-waymo-20190226-s3': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 3, "
        "column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode at the intersection of Miramonte '
        'Avenue and Covington Road in Los Altos when it was involved in a collision. The Waymo AV was traveling '
        'northbound on Miramonte Avenue, when it reached a four-way stop sign intersection. The Waymo AV stopped '
        'to yield to another vehicle at the intersection, at which time a passenger vehicle rear-ended the Waymo '
        'AV at approximately 39 MPH. At the time of the collision the Waymo AV had been stopped for '
        'approximately 1.5 seconds. The Waymo AV sustained major damage to its rear bumper, rear hatch, and rear '
        'quarter panels, and the passenger vehicle sustained major damage to its front bumper, hood, and front '
        'quarter panels. First responders attended to the scene, but neither party reported injuries.'),
    'csvr-waymo-20190515-s11': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "11, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) in autonomous mode was yielding to check for cross traffic '
        'while in the slip lane to turn from southbound Shoreline Boulevard to westbound El Camino Real in '
        'Mountain View when it was rear-ended by a passenger vehicle at approximately 5 MPH. The Waymo AV '
        'sustained minor damage to its rear bumper, and the passenger vehicle had minor damage to its front '
        'bumper. The two Waymo AV operators reported neck/back pain but declined medical attention at the scene.'),
    'csvr-waymo-20190529-s15': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "15, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) in autonomous mode was stopped in traffic while in the leftmost '
        'lane on southbound San Antonio Road headed toward Charleston Road in Palo Alto when it was rear-ended '
        'by a passenger vehicle maneuvering into the Waymo AV’s lane at approximately less than 1 MPH. The Waymo '
        'AV sustained minor scratches to its rear sensor, and the passenger vehicle left the scene. There were '
        'no injuries reported at the scene.'),
    'csvr-waymo-20190616-s18': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "18, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode on the off-ramp from westbound '
        'Alma Street to southbound Oregon Expressway in Palo Alto when it was rear-ended. The Waymo AV was '
        'yielding to cross-traffic when a passenger vehicle made contact with the Waymo AV’s rear bumper at '
        'approximately 5 MPH. The Waymo AV sustained minor damage to the rear bumper, and the passenger vehicle '
        'left the scene without stopping or exchanging information. The Waymo AV driver complained of neck, '
        'back, and nose pain and was treated at the scene by emergency responders.'),
    'csvr-waymo-20191010-s34': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "34, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode in traffic at a red light on '
        'southbound Rengstorff Avenue at Central Expressway in Mountain View when it was rear-ended by a '
        'passenger vehicle. The passenger vehicle made contact with the Waymo AV’s rear bumper at '
        'approximately 1 MPH. The Waymo AV sustained minor damage to its rear bumper, and the passenger '
        'vehicle sustained minor damage to its front bumper. No injuries were reported.'),
    'csvr-waymo-20191014-s37': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "37, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode on westbound Cuesta Drive at S. '
        'San Antonio Road in Los Altos when it was rear-ended. The Waymo AV was preparing to make a right-on-red '
        'from Cuesta Drive onto northbound S. San Antonio Road and was yielding to cross-traffic when a '
        "passenger vehicle made contact with the Waymo AV's rear bumper at approximately 3 MPH. The Waymo AV "
        'sustained minor damage to its rear bumper, and the passenger vehicle sustained no damage to its front '
        'bumper. No injuries were reported.'),
    'csvr-waymo-20191016-s38': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "38, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode on northbound Distel Drive at El '
        'Camino Real in Los Altos when it was rear-ended. The Waymo AV was preparing to make a right-on-red from '
        'Distel Drive onto eastbound El Camino Real and was yielding to cross-traffic when a passenger vehicle '
        'made contact with the Waymo AV’s rear bumper at approximately 1 MPH. The Waymo AV sustained minor '
        'damage to its rear bumper, and the passenger vehicle sustained minor damage to its front bumper. No '
        'injuries were reported.'),
    'csvr-waymo-20200214-s53': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "53, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode turning right from eastbound '
        'Park Drive onto southbound Miramonte Avenue in Mountain View when it was rear-ended. The Waymo AV was '
        'yielding to approaching traffic when a passenger vehicle made contact with the Waymo AV’s rear bumper '
        'at approximately 6 MPH. The Waymo AV sustained minor damage to its rear bumper, and the passenger '
        'vehicle sustained minor damage to its front bumper. No injuries were reported at the scene.'),
    'csvr-waymo-20201229-s69': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "69, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) was traveling northbound on 3rd Street in San Francisco in '
        'manual mode when it was rear-ended. The Waymo AV was traveling in autonomous mode at approximately '
        '30 MPH in the leftmost lane as it approached the intersection at 24th Street. In this location '
        'there are traffic pylons on the left edge of the leftmost lane that separate this lane from the '
        'municipal tram line that operates in the median of 3rd Street. As the Waymo AV approached the '
        'intersection, a San Francisco MUNI city bus traveling at approximately 40 MPH in the right adjacent '
        'lane began to overtake the Waymo AV from the right, while moving toward the Waymo’s lane of travel. '
        'Due to the encroaching city bus and the pylons on the left edge of the Waymo AV’s lane, the Waymo '
        'AV began to brake. The Waymo AV test driver disengaged autonomous mode and took control of the '
        'Waymo AV. Approximately 1 second later, the passenger vehicle behind the Waymo AV made contact with '
        'the Waymo AV’s rear bumper at approximately 27 MPH. The Waymo AV was traveling approximately 4 MPH. '
        'The Waymo AV sustained significant damage to its rear bumper, and the passenger vehicle sustained '
        'significant damage to its front bumper. The driver of the passenger vehicle and the Waymo AV test '
        'driver were transported to receive medical attention. The Waymo AV co-driver reported minor '
        'injuries but did not receive medical attention. Amended Sections 3 and 4.'),
    'csvr-waymo-20210709-s89': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "89, column 'Accident Detail Description'), transcribed",
        'A Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, California was in a collision '
        'involving a passenger vehicle at Bush Street and Grant Avenue. The Waymo AV was stopped in traffic '
        'while in autonomous mode when the passenger vehicle approached from behind while changing lanes. The '
        'passenger vehicle struck the rear of the stopped Waymo AV traveling at 5.5 miles per hour and left the '
        'scene. The left rear bumper of the Waymo AV sustained minor damage.'),
    'csvr-waymo-20211018-s101': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "101, column 'Accident Detail Description'), transcribed",
        'On October 18, 2021 at 12:57 PM PDT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'CA was in a collision involving an SUV at Cesar Chavez and Evans Avenue. As the Waymo AV approached a '
        'right turn from Cesar Chavez onto Evans Avenue, it braked behind stopped traffic. An SUV following '
        'behind the Waymo AV made contact with the rear of the Waymo AV. At the time of the impact, the Waymo '
        'AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present in the driver’s seating '
        'position. The Waymo AV sustained minor damage to its rear bumper and trunk, and the SUV sustained minor '
        'damage to its front bumper and hood.'),
    'csvr-waymo-20211207-s118': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "118, column 'Accident Detail Description'), transcribed",
        'On December 7, 2021 at 10:47 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'CA was in a collision involving an SUV at Oak Street at Stanyan Street. While in autonomous mode, the '
        'Waymo AV came to a stop at a stop sign on Oak Street. While the ADV was stopped, waiting for a '
        'pedestrian to cross and for traffic on Stanyan Street to clear, an SUV approached the Waymo AV from '
        'behind and made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV’s Level '
        '4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s seating position). '
        'The Waymo AV sustained minor damage to the rear bumper.'),
    'csvr-waymo-20220103-s122': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "122, column 'Accident Detail Description'), transcribed",
        'On January 3, 2021 at 9:00 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a heavy truck at the northbound merge lane on the 100 block of '
        'Bayshore Boulevard. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous '
        'mode, and a test driver was present (in the driver’s seating position). While attempting a merge onto '
        'northbound Bayshore Boulevard from southbound Bayshore Boulevard, the Waymo AV came to a stop to yield '
        'for approaching traffic on the right. The Waymo AV was rear ended by the truck, causing minor damage to '
        'the right rear bumper of the Waymo AV. The truck sustained damage to the left front bumper.'),
    'csvr-waymo-20220128-s127': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "127, column 'Accident Detail Description'), transcribed",
        'On January 28, 2022 at 6:30 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Franklin Street at Golden Gate Avenue. '
        'The Waymo AV was stopped at a red light on northbound Franklin Street at Golden Gate Avenue. After the '
        'traffic light turned green and the Waymo AV had begun to accelerate, the passenger vehicle behind the '
        'Waymo AV struck the rear of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was '
        'engaged in autonomous mode, and a test driver was present (in the driver’s seating position). The Waymo '
        'AV sustained minor damage, and the trailing passenger vehicle sustained minor damage.'),
    'csvr-waymo-20220211-s132': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "132, column 'Accident Detail Description'), transcribed",
        'On February 11, 2022 at 5:36 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Market Street and Valencia Street. The '
        'Waymo AV was approaching stopped traffic in the left turn lane on Market Street at Valencia Street when '
        'a passenger vehicle approached from behind and made contact with the rear bumper of the Waymo AV. The '
        'other vehicle left the scene without exchanging information. At the time of the impact, the Waymo AV’s '
        'Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s seating '
        'position). The Waymo AV sustained minor damage.'),
    'csvr-waymo-20220214-s134': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "134, column 'Accident Detail Description'), transcribed",
        'On February 14, 2022 at 3:02 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Kansas Street at 16th Street. The Waymo '
        'AV was stopped at a red light facing north on Kansas Street at the 16th Street intersection in '
        'autonomous mode. While the traffic light was still red, the vehicle immediately behind the Waymo AV '
        'began to accelerate and made contact with the rear bumper of the Waymo AV. At the time of the impact, '
        'the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the '
        'driver’s seating position). The Waymo AV sustained minor damage.'),
    'csvr-waymo-20220517-s160': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "160, column 'Accident Detail Description'), transcribed",
        'On May 17, 2022 at 1:26 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger car on Stanyan Street at McAllister Street. The '
        'Waymo AV was proceeding south on Stanyan Street in autonomous mode, and preparing to make a left turn '
        'onto McAllister Street. As the Waymo AV entered the intersection, it slowed to yield to northbound '
        'traffic on Stanyan Street. A passenger car approached from behind and made contact with the rear of the '
        'Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a '
        'test driver was present (in the driver’s seating position). Both vehicles sustained minor damage.'),
    'csvr-waymo-20221108-s197': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "197, column 'Accident Detail Description'), transcribed",
        'On November 8, 2022 at 9:34 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger car on 2nd Street at Minna Street. The Waymo AV was '
        'stopped in traffic on northbound 2nd Street in autonomous mode. A passenger car that had been stopped '
        'behind the Waymo AV passed on the left side, crossing the double yellow line and making contact with '
        'the Waymo AV’s rear left sensor housing. The passenger car immediately left the scene. At the time of '
        'the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present '
        '(in the driver’s seating position). The Waymo AV sustained damage.'),
    'csvr-waymo-20230122-s209': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "209, column 'Accident Detail Description'), transcribed",
        'On January 22, 2023 at 5:08 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Bayshore Boulevard at Jerrold Avenue. '
        'The Waymo AV was traveling north on Bayshore Boulevard when, upon entering the intersection at Jerrold '
        'Avenue, a passenger vehicle which had previously been stopped at a red light, proceeded through the red '
        'light. The passenger vehicle approached from the left and made contact with the left rear bumper of the '
        'Waymo AV. The other vehicle immediately left the scene of the collision. At the time of the impact, the '
        'Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s '
        'seating position). Both vehicles sustained damage.'),
    'csvr-waymo-20230320-s224': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "224, column 'Accident Detail Description'), transcribed",
        'On March 20, 2023 at 10:43 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in Los Angeles, '
        'California was in a collision involving an SUV on Venice Boulevard at La Cienega. The Waymo AV was '
        'stopped in the center lane of a three-lane road behind a passenger vehicle for a red light facing '
        'southwest on Venice Boulevard at La Cienega in autonomous mode. The light turned green while '
        'cross-traffic remained backed up in the intersection. The Waymo AV nudged forward and slowed to a stop, '
        'yielding for the blocking cross traffic. A passenger vehicle that had been stopped behind the Waymo AV '
        'proceeded forward and made contact with the rear of the Waymo AV. At the time of the impact, the Waymo '
        'AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s seating '
        'position). The Waymo AV sustained damage.'),
    'csvr-waymo-20230506-s241': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "241, column 'Accident Detail Description'), transcribed",
        'On May 6, 2023 at 8:48 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Post Street at Webster Street. While '
        'traveling west on Post Street, the Waymo AV was executing a pullover maneuver in autonomous mode and '
        'made contact with the left rear bumper of a parked vehicle. At the time of the impact, the Waymo AV’s '
        'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.'),
    'csvr-waymo-20230605-s246': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "246, column 'Accident Detail Description'), transcribed",
        'On June 5, 2023 at 12:53 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a van in a parking lot at 3911 3rd Street. The Waymo AV came to '
        'a stop while yielding to a pickup truck which was reversing into a perpendicular parking space in front '
        'of the Waymo AV. While the Waymo AV was stopped, a van which was in a parking space immediately to the '
        'right of the Waymo AV began reversing out of the parking space. The rear of the van made contact with '
        'the right side of the Waymo AV. The Waymo AV sustained damage. At the time of the impact, the Waymo '
        'AV’s Level 4 ADS was engaged in autonomous mode.'),
    'csvr-waymo-20240319-s304': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "304, column 'Accident Detail Description'), transcribed",
        'On March 19, 2024 at 7:18 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on Division Street at 9th Street. The Waymo AV '
        'was traveling west on Division Street after having stopped at the stop sign at Vermont Street and was '
        'approaching the intersection with 9th Street when a passenger car approached from behind the Waymo AV, '
        'ran the stop sign at Vermont Street, and made contact with the rear of the Waymo AV. The front of the '
        'passenger car made continuous contact with the rear of the Waymo AV while both vehicles were still in '
        'motion for a short period of time before the passenger car slowed down and separated from the AV. The '
        'Waymo AV proceeded through the intersection with 9th Street and came to a stop on Division Street west '
        'of the intersection with 9th Street. The passenger car then accelerated and the front right corner of '
        'the passenger car made contact with the rear left corner of the stationary Waymo AV. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage."),
    'csvr-waymo-20240330-s307': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "307, column 'Accident Detail Description'), transcribed",
        'On March 30, 2024 at 1:33 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving an SUV on Jerrold Avenue at Barneveld Avenue. The Waymo AV was '
        'stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the intersection '
        'making a left turn from Barneveld Avenue onto Jerrold Avenue when the front right corner of the SUV, '
        'which was traveling behind the Waymo AV, made contact with the rear left corner of the Waymo AV. At the '
        "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
        'damage.'),
    'csvr-waymo-20240513-s311': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "311, column 'Accident Detail Description'), transcribed",
        'On May 13, 2024 at 12:58 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, CA was '
        'in a collision involving a passenger car on eastbound Interstate 10 between Exit 2 and Exit 3A. The '
        'Waymo AV was traveling with a test driver present behind a box truck in the number 3 lane of eastbound '
        'Interstate 10 near the Bundy Drive overpass when a passenger car traveling at a high rate of speed '
        'approached the Waymo AV from behind. The passenger car partially entered the number 2 lane as the front '
        'right corner of the passenger car made contact with the rear left corner of the Waymo AV. The passenger '
        'car then made contact with the center median and came to a stop. The Waymo AV was transitioned into '
        'manual mode, and the test driver stopped the Waymo AV to the right-hand shoulder. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode, and a test driver was present (in "
        'the driver’s seating position). Both vehicles sustained damage.'),
    'csvr-waymo-20240603-s315': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "315, column 'Accident Detail Description'), transcribed",
        'On June 3, 2024 at 4:54 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in Marina Del Rey, '
        'California was in a collision involving a passenger car on Admiralty Way at Bali Way. The Waymo AV was '
        'making a left turn from the rightmost dedicated left turn lane on Admiralty Way into lane two of three '
        'lanes in the eastbound direction of Bali Way. A passenger car was also making a left turn from the '
        'leftmost dedicated left turn lane (leftmost lane). The passenger car had made the turn onto Bali Way '
        'and was partially in the number 1 lane (leftmost) and partially in the number 2 lane (middle) when the '
        'front passenger side of the passenger car made contact with the rear driver side of the Waymo AV, which '
        'was traveling in the number 2 lane (middle). At the time of the impact, the Waymo AV’s Level 4 ADS was '
        'engaged in autonomous mode, and a test driver was present (in the driver’s seating position). Both '
        'vehicles sustained damage.'),
    'csvr-waymo-20240605-s317': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "317, column 'Accident Detail Description'), transcribed",
        'On June 5, 2024 at 1:12 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger car on 29th Avenue near Lawton Street. The Waymo AV '
        'was parked at the curb on the right side of 29th Avenue when a passenger car in front of the Waymo AV '
        'began to reverse to parallel park. The passenger car’s rear driver side corner made contact with the '
        'front driver side corner of the parked Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS '
        'was engaged in autonomous mode. The Waymo AV sustained damage.'),
    'csvr-waymo-20240801-s325': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "325, column 'Accident Detail Description'), transcribed",
        'On August 1, 2024 at 10:05 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in Los Angeles, '
        'California was in a collision involving an SUV on W. Jefferson Boulevard near La Brea Avenue. The Waymo '
        'AV was stopped in traffic in the leftmost lane of a two-lane section of westbound W. Jefferson '
        'Boulevard, just before the road widened to include a dedicated left turn lane in lane three. While the '
        'Waymo AV remained stopped, an SUV approached the Waymo AV from behind and partially entered the '
        'oncoming lanes of W. Jefferson Boulevard to maneuver around the Waymo AV and proceed into the dedicated '
        'left turn lane. As the SUV was passing the stopped Waymo AV, the passenger side of the SUV made contact '
        'with the rear driver side corner of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS '
        'was engaged in autonomous mode. Both vehicles sustained damage and the SUV left the scene.'),
    'csvr-waymo-20240918-s334': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "334, column 'Accident Detail Description'), transcribed",
        'On September 18, 2024 at 8:44 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a van on Potrero Avenue at 16th Street. The Waymo AV was '
        'stopped in a queue of traffic in the leftmost of two through lanes on southbound Potrero Avenue at the '
        'intersection with 16th Street when a van traveling behind the Waymo AV passed the Waymo AV on the left '
        'to enter the dedicated left turn lane. The passenger side of the van made contact with the rear left '
        'sensor of the Waymo AV. Without stopping, the van then crossed the double yellow line to the northbound '
        'side of Potrero Avenue, turned left onto eastbound 16th Street, and left the scene. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode, and a test driver was present (in "
        "the driver's seating position). The Waymo AV sustained damage to the rear left sensor housing and "
        'assembly.'),
    'csvr-waymo-20241214-s355': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 355, column 'Accident Detail Description'), transcribed",
        'On December 14, 2024 at 9:53 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San '
        'Francisco, California was in a collision involving a heavy truck on Alabama Street at Cesar Chavez '
        'Street. The Waymo AV was stopped facing a malfunctioning traffic light on southbound Alabama Street '
        'at the intersection with Cesar Chavez Street. While the Waymo AV remained stopped and the traffic '
        'light was not illuminated, a heavy truck that had been stopped behind the Waymo AV entered the '
        'oncoming lane of Alabama Street to maneuver around the Waymo AV. As the heavy truck was passing the '
        'stopped Waymo AV, the passenger side of the heavy truck made contact with the rear driver side '
        'corner of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in '
        'autonomous mode. Both vehicles sustained damage.'),
    'nhtsa-sgo-ads-30270-8627-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8627,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2024 at 5:27 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Ariz'
        'ona was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was stopped in traffic in a '
        'one-lane section of northbound [XXX], just before the road widened to include a dedicated left turn '
        'lane in the left adjacent lane ahead. While the Waymo AV remained stopped, an SUV approached the Way'
        'mo AV from behind and began to maneuver around the left side of the Waymo AV to proceed into the ded'
        'icated left turn lane. While passing the stopped Waymo AV, the passenger side of the SUV made contac'
        "t with the driver side rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS w"
        'as engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under R'
        'equest No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with a'
        'dditional information as it may become available.'),
    'csvr-waymo-20241227-s358': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "358, column 'Accident Detail Description'), transcribed",
        'On December 27, 2024 at 10:16 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger car on Larkin Street at Olive Street. The Waymo AV '
        'was traveling northbound on Larkin Street when a passenger car traveling directly in front of the Waymo '
        'AV stopped in lane, and began to reverse to parallel park at the curb. While the passenger car was '
        'reversing, the rear driver side of the passenger car made contact with the front passenger side of the '
        'stationary Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous '
        'mode, and a test driver was present (in the driver’s seating position). Both vehicles sustained damage.'),
    'csvr-zoox-20191011-s35': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 35, column 'Accident Detail Description'), transcribed",
        'The stationary Zoox vehicle was in autonomous mode heading northbound on Union St. Contact occurred '
        'when the Zoox vehicle was stopped at a stop sign at the intersection of Union St. and Grant St., '
        'when it was rear-ended by an electric scooter. The scooter was following closely behind the Zoox '
        'vehicle and the scooter driver was not focused on the Zoox vehicle in front of it, when the '
        "scooter's front tire made contact with the rear bumper of the Zoox vehicle. There were no injuries."),
    'csvr-zoox-20210511-s81': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "81, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomous mode began to slow down during an unprotected left turn to yield for cross '
        'traffic entering the lane from the right. A passenger vehicle from behind did not slow and made contact '
        'with the rear sensors of the Zoox vehicle. There were no injuries and the police were not called.'),
    'csvr-zoox-20220205-s130': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "130, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomous mode was stopped at a traffic light on Brannan Street at 7th Street when a '
        'passenger vehicle hit the Zoox vehicle from behind. The passenger vehicle left the scene without '
        'exchanging information. There were no injuries and the police were not called.'),
    'csvr-zoox-20230208-s212': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "212, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomy was stopped with brake lights illuminated in traffic southbound on '
        'Embarcadero Street towards Folsom Street. When traffic ahead began to move the Zoox vehicle was '
        'appropriately following the car ahead at low speed when it was rear ended by Vehicle #2 at low speed. '
        'The other party did not stop to exchange information and left the scene. There were no injuries and '
        'police were not called.'),
    'csvr-zoox-20230211-s213': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "213, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomous mode was slowing to a stop with brake lights illuminated behind traffic on '
        'northbound 5th Street near Jesse Street when a vehicle behind made contact at approximately 10mph. '
        'There were no injuries and police were not called.'),
    'csvr-zoox-20230517-s243': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "243, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomous mode was traveling north on Harrison St. The Zoox vehicle began coming to '
        'a gradual stop for traffic ahead when it was rear ended by vehicle 2 at low speed. There was minor '
        'damage and police were not called. The Zoox operator reported a "sore neck and back."'),
    'csvr-zoox-20240115-s294': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "294, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle (Vehicle 1) in autonomy was traveling on southbound Stockton St near Union St in San '
        'Francisco. The Zoox vehicle slowed to a gradual stop with brake and hazard lights activated during a '
        'simulated pick up-drop off maneuver when it was rear-ended by a minivan (Vehicle 2). The rear bumper of '
        'the Zoox vehicle sustained minor damage. There were no reported injuries, and police were not called. '
        'Zoox vehicle camera footage shows that the driver of the minivan may not have been looking ahead at the '
        'roadway prior to and at the time of contact.'),
    'csvr-zoox-20240716-s322': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "322, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle (Vehicle 1) in autonomous mode was stopped at a stop sign waiting for traffic to clear '
        'to make a left turn from northeast bound King Street onto 7th Street in San Francisco. A passenger car '
        '(Vehicle 2) was stopped directly behind the Zoox vehicle apparently in the process of turning right '
        'onto 7th Street. As the Zoox vehicle advanced and then came to a stop as it yielded to cross traffic, '
        'the passenger car tried to pass the Zoox vehicle on the right side and contacted the Zoox vehicle. The '
        'front bumper on the passenger car and rear bumper on the Zoox vehicle sustained minor damage. There '
        'were no reported injuries and the police were not called.'),
    'nhtsa-sgo-ads-30270-7813-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7813,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 10:37 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco'
        ', California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was trave'
        'ling southwest on [XXX] in the far left lane and stopped in a queue of traffic at a red light at the'
        ' intersection with [XXX]. After the light turned green, the Waymo AV began to slowly move ahead whil'
        'e continuing to yield to the traffic ahead when the front of the pickup truck following behind the W'
        "aymo AV made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level "
        '4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash '
        'under Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Way'
        'mo may supplement or correct its reporting with additional information as it may become available.'),
    'dmvca-apple-20240126-r555': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 555, column '
        '"Accident Detail Description")',
        'On January 26th, a test vehicle operating with the automated driving system engaged was traveling '
        'Eastbound on Interstate 580 in Castro Valley when a nearby semi-trailer truck merging from Interstate '
        '238 generated a draft that projected road debris onto the test vehicle. No injuries were reported and '
        'law enforcement was not called to the scene. The test vehicle sustained minor damage.'),
    'dmvca-cruise-20190107-r0': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 0, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“Cruise AV”), operating in conventional mode, was making a left turn from '
        'northeast bound Folsom Street onto northwest bound 11th Street when a scooterist, attempting to pass '
        'the Cruise AV on the left, made contact with the front left side of the Cruise AV, damaging the front '
        'left fender, radar, and wheel well of the Cruise AV. The scooterist reported injuries and emergency '
        'services and the police arrived at the scene, but the scooterist declined medical treatment. No police '
        'report was available at the time of the filing of this report.'),
    'dmvca-cruise-20191107-r89': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 89, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was traveling eastbound on '
        '24th Street at the intersection with Mission Street when the Cruise AV yielded to an electric '
        'scooterist traveling northbound on Mission Street and violating a red light. The driver of the Cruise '
        'AV disengaged from autonomous mode and, shortly thereafter, the electric scooterist made contact with '
        'the right rear corner of the Cruise AV, damaging the Cruise AV’s right rear fascia and brake light. The '
        'electric scooterist left the scene without exchanging information. There were no injuries and police '
        'were not called.'),
    'dmvca-cruise-20200725-r132': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 132, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“Cruise AV”) being driven in conventional mode was involved in a '
        'single-car collision on westbound Taraval Street near the intersection with 21st Avenue. After '
        'completing a right turn onto Taraval from 21st, the driver of the Cruise AV turned into a parallel '
        'parking space and made contact with the curb, damaging the Cruise AV’s front right tire. There were '
        'no injuries and police were not called.'),
    'dmvca-cruise-20230814-r511': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 511, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“AV”), operating in driverless autonomous mode, was traveling southbound '
        'on Albion Street between 16th Street and Camp Street. At the same time, a Ford pickup truck was '
        'traveling northbound on Albion Street partially in the AV’s lane of travel. The AV stopped due to '
        'limited space to proceed forward due to the encroaching Ford pickup truck, and, shortly thereafter, the '
        'Ford pickup truck made contact with the AV, damaging the AV’s rear driver side bumper fascia, rear '
        'driver side quarter panel and rear driver side wheel molding. The driver of the Ford pickup truck left '
        'the scene without exchanging information. There were no reported injuries.'),
    'dmvca-cruise-20230817-r515': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 515, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("AV"), operating in driverless autonomous mode, was at a complete stop in '
        'response to a stop sign on eastbound 17th Street at the intersection with Vermont Street. As the AV '
        'began to proceed straight, a gray Honda Odyssey traveling westbound on 17th Street on the opposite side '
        'of the intersection from the AV entered the intersection and veered into the AV’s lane of travel. The '
        'AV stopped in response as the Honda Odyssey continued traveling in the AV’s lane of travel through the '
        'intersection and, shortly thereafter, the Honda Odyssey made contact with the AV, damaging the front '
        'and rear driver side doors, front driver side radar assembly and rear driver side tire of the AV. The '
        'parties exchanged information. There were no reported injuries and the AV was towed from the scene.'),
    'dmvca-cruise-20230927-r531': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 531, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle (“AV”), operating in driverless autonomous mode, was traveling northbound '
        'on 2nd Street between Stillman Street and Bryant Street. As the AV was approaching the intersection '
        'with Stillman Street, a blue Model 3 Tesla exited out of a parking garage into the AV’s lane of travel. '
        'The AV braked and, shortly thereafter, the AV made contact with the Model 3 Tesla, damaging the AV’s '
        'front bumper fascia and front passenger side wheel opening molding. The driver of the Model 3 Tesla '
        'left the scene without exchanging information. There were no reported injuries. The driver of the Model '
        '3 Tesla later reported damages.'),
    'dmvca-waymo-20210404-r172': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 172, '
        'column "Accident Detail Description")',
        'A Waymo Autonomous Vehicle (“Waymo AV”) traveling northbound on Jones Street approaching Clay '
        'Street in San Francisco was involved in a collision. After the Waymo AV made a right turn from '
        'Pleasant Street in autonomous mode, the Waymo AV test driver disengaged autonomous mode to maneuver '
        'past an oncoming vehicle on Jones Street that was drifting toward the Waymo AV. While in manual '
        'mode, the Waymo AV’s passenger side view mirror then made contact with an unoccupied parked '
        'passenger vehicle’s driver side view mirror at approximately 6 MPH. The Waymo AV sustained minor '
        'damage to its passenger side view mirror. The unoccupied passenger vehicle’s driver-side mirror was '
        'cracked, but most or all of the damage appeared to have been pre-existing. No other damage was '
        'observed to the unoccupied passenger vehicle. No injuries were reported at the scene.'),
    'dmvca-waymo-20210712-r196': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 196, column '
        '"Accident Detail Description")',
        'On July 12, 2021 at 3:10 PM PDT, a Waymo Autonomous Vehicle (“Waymo AV”) was in a collision involving a '
        'van at Broadway and Gough Street in San Francisco. The Waymo AV, while in autonomous mode, was waiting '
        'to make a left turn and yielding to oncoming traffic, when the test driver (in the driver’s seating '
        'position) transitioned to manual mode and proceeded with a left turn manually. During the left turn, an '
        'approaching van struck the right side of the Waymo AV. At the time of the impact, the Waymo AV was in '
        'manual mode.'),
    'dmvca-waymo-20211008-r227': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 227, column '
        '"Accident Detail Description")',
        'On October 8, 2021 at 6:39 PM PDT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle at Mission Street at Avalon Avenue. While '
        'traveling northwest on Mission Street in autonomous mode, the Waymo AV navigated around a double-parked '
        'vehicle stopped in the right lane. After re-entering the right lane, the Waymo AV came to a complete '
        'stop behind a second passenger vehicle, at which time the driver of the Waymo AV transitioned into '
        'manual mode. The second passenger vehicle reversed into the Waymo AV, making contact with its front '
        'bumper. Both vehicles sustained minor bumper damage.'),
    'dmvca-waymo-20220208-r284': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 284, '
        'column "Accident Detail Description")',
        'On February 8, 2022 at 8:56 AM PST, a Waymo Autonomous Vehicle (“Waymo AV”) operating in San '
        'Francisco, California was in a collision involving a passenger vehicle on Harrison Street at 9th '
        'Street. The Waymo AV was traveling southbound on Harrison Street in manual mode, and began slowing '
        'for a red light as it approached the intersection of 9th Street. The Waymo AV was in the second '
        'lane from the left on a one-way street. A passenger in a taxi cab that was stopped in the lane to '
        'the left of the Waymo AV opened the rear passenger door as the Waymo AV was coming to a stop. The '
        'edge of the taxi cab’s door made contact with the Waymo AV. At the time of the impact, the Waymo '
        'AV’s Level 4 ADS was not engaged and a test driver was operating the Waymo AV in manual mode. The '
        'other vehicle sustained minor damage.'),
    'dmvca-waymo-20220511-r333': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 333, column '
        '"Accident Detail Description")',
        'On May 11, 2022 at 9:19 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a SUV on 24th Street and Capp Street. The Waymo AV was '
        'attempting to make a right turn from 24th Street onto Capp Street while yielding to a pedestrian in the '
        'adjacent crosswalk in autonomous mode. A SUV approaching from behind the Waymo AV passed on the left '
        'side, making contact with the Waymo AV’s rear left sensor housing. The Waymo AV operator transitioned '
        'the system from autonomous to manual mode just before the moment of impact. The SUV immediately left '
        'the scene. At the time of the impact, the Waymo AV’s Level 4 ADS was not engaged and a test driver was '
        'operating the Waymo AV in manual mode. The Waymo AV sustained minor damage.'),
    'nhtsa-sgo-ads-30791-10003-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30791-10003'
        ', version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On Feb [XXX], 2025 at 06:31 PM PT, the blind spot sensor pod of our autonomous vehicle (AV) made con'
        'tact with a parked passenger car on [XXX], Santa Clara, CA. The AV was making a right turn along the'
        '[XXX], traveling at 16 mph. Due to an inaccurate map version downloaded on the AV causing the AV to '
        'drive close to the parked vehicles on the side of the street, the safety driver disengaged the AV. A'
        'fter disengagement, the right side sensor pod of the AV made contact with the left side rear view mi'
        'rror of a passenger vehicle parked on the side of the Kingsbury Cir. At the time of the impact, the '
        "AV's Level 4 ADS was not engaged and the safety driver was operating the AV in manual mode. Both veh"
        'icles sustained minor damage.'),
    'dmvca-waymo-20220605-r349': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 349, column '
        '"Accident Detail Description")',
        'On June 5, 2022 at 10:07 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Bush Street and Gough Street. The Waymo '
        'AV was stopped in autonomous mode behind stopped traffic facing east on Bush Street. The passenger '
        'vehicle ahead of the Waymo AV transitioned into reverse and began to accelerate, making contact with '
        'the front sensor of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in '
        'autonomous mode, and a test driver was present (in the driver’s seating position). Both vehicles '
        'sustained minor damage.'),
    'dmvca-waymo-20230507-r466': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 466, column '
        '"Accident Detail Description")',
        'On May 7, 2023 at 3:27 PM PDT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a cyclist on Bay Street near Mason Street. The Waymo AV was '
        'traveling westbound in the left lane on Bay Street and had just passed Mason Street when it detected an '
        'oncoming pickup truck traveling eastbound in the Waymo AV’s lane. The Waymo AV stopped and the pickup '
        'truck re-entered the correct lane for eastbound traffic and passed the Waymo AV. The pickup truck was '
        'immediately followed by a large group of cyclists traveling eastbound in multiple lanes of the roadway, '
        'including the right lanes and on the wrong side of the double-yellow centerline. The Waymo AV remained '
        'stopped as the oncoming cyclists rode around both sides of the Waymo AV. One cyclist then made contact '
        'with the front of the stationary Waymo AV, and then immediately left the scene. At the time of the '
        'impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage.'),
    'dmvca-waymo-20230711-r497': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 497, column '
        '"Accident Detail Description")',
        'On July 11, 2023 at 10:13 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Martin Avenue at Mullen Avenue. While '
        'completing a right turn from Martin Avenue onto Mullen Avenue in autonomous mode, the Waymo AV slowed '
        'to a stop while entering a narrow roadway. As the Waymo AV started to slowly proceed forward, the test '
        'driver transitioned the vehicle to manual mode and proceeded forward, making contact with a parked '
        'passenger vehicle. At the time of the impact, the Waymo AV’s Level 4 ADS was not engaged and a test '
        'driver was operating the Waymo AV in manual mode. Both vehicles sustained damage.'),
    'dmvca-waymo-20241016-r620': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 620, column '
        '"Accident Detail Description")',
        'On October 16, 2024 at 5:27 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a van in an underground parking lot at 1160 Mission Street. Two '
        'Waymo AVs were stopped at neighboring junctures of a tight T-instersection of the lot. The first Waymo '
        'AV was preparing to make a right turn, while yielding to the other Waymo AV. While the Waymo AVs '
        'remained stopped, a van that had been traveling behind the first Waymo AV entered the oncoming lane to '
        'maneuver around the left side of the Waymo AV. The passenger side of the van then made contact with the '
        'rear driver side of the stopped Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was '
        'engaged in autonomous mode. Both vehicles sustained damage.'),
    'dmvca-waymo-20241202-r634': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 634, column '
        '"Accident Detail Description")',
        'On December 2, 2024 at 10:54 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in Los Angeles, '
        'California was in a collision involving a plastic crate on East 3rd Street at South Central Avenue. The '
        'Waymo AV was traveling westbound in the center lane on East 3rd Street, crossing the intersection with '
        'South Central Avenue when the front passenger side of the Waymo AV made contact with a plastic crate '
        'that was in the roadway within the Waymo AV’s lane of travel. The contact with the Waymo AV caused the '
        'crate to move into the adjacent right lane, which was occupied by a scooterist. The front tire of the '
        'scooter made contact with the crate and the scooter and scooterist fell. At the time of the impact, the '
        'Waymo AV’s Level 4 ADS was engaged in autonomous mode. Given the speed at which the scooter was '
        'traveling at the time of the contact, the scooter may have sustained damage.'),
    'dmvca-zoox-20220428-r329': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 329, column '
        '"Accident Detail Description")',
        'A Zoox vehicle in autonomous mode came to a complete stop at the T-junction stop sign at Colin P. Kelly '
        'Jr. St. and Brannan St. and yielded to oncoming traffic from the left. Due to traffic flow, the driver '
        'then disengaged autonomous mode and reversed, making contact with a vehicle that had approached from '
        'the rear and was attempting to pass the Zoox vehicle to make a right turn. There were no injuries and '
        'the police were not called.'),
    'dmvca-zoox-20220823-r376': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 376, column '
        '"Accident Detail Description")',
        'A Zoox vehicle in autonomy had made a right turn from Oakdell Rd. onto Santa Cruz Ave. in Menlo Park, '
        'CA and was preparing to make an immediate, unprotected left turn onto Sharon Road. The Zoox vehicle was '
        'slowing and moving at approximately 2 mph with its brake lamps and left turn indicator illuminated, '
        'yielding to an oncoming vehicle with the right of way. A following vehicle - traveling at approximately '
        "24 mph - then struck the Zoox vehicle's right rear bumper, and that vehicle's driver airbag appeared to "
        'have deployed on impact. The Zoox operator disengaged autonomy, proceeded with the left turn, and '
        'pulled over. The following vehicle continued its path of travel, veered out of the lane, and collided '
        'with a tree on the left side of the road. The Menlo Park Police Department was called to the scene. Two '
        'Zoox operators sustained minor injuries and it is unknown if the driver of the other vehicle sustained '
        'injuries.'),
    'nhtsa-sgo-ads-10003-3210-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 10003-3210, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'All of the data in this report and the following text is an excerpt from TuSimples original '
        "submission (30370-2949-1) and constitutes Navistars sole understanding of this event. TuSimple's "
        'position is that this event does not meet the criteria for reporting under the SGO. Specifically, '
        'the L4 ADS was not in operation at any point in the 30 seconds prior to making contact with the '
        'concrete barrier. The event occurred as follows: As the truck was being operated on the highway, '
        'within its mapped ODD, the driver and test engineer attempted to engage the ADS. However, the ADS '
        'was not functional at that moment due to the computer unit not having been initialized, and should '
        'not have been attempted to be activated. In short, this was a failed attempt to engage the system '
        'as a result of human error. The system has now been modified to prevent the ADS from attempting to '
        'engage unless the health of the system is fully functional to prevent human error from repeating '
        'this event. When the erroneous attempt to engage occurred, the uninitialized vehicle control unit '
        'rotated the steering to the left, causing the truck to veer left. The safety driver took control of '
        'the steering, and was able to steer accordingly, but not before the left front truck tire and left '
        'front quarter panel came into contact with the concrete barrier to the left of the lanes of travel.'),
    'nhtsa-sgo-ads-1420-7995-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 1420-7995, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The subject vehicle (autonomous vehicle - AV) was stopped at a red traffic light, in a queue of '
        'vehicles, heading west on [XXX], with autonomous driving (AD) mode engaged. Once the light turned '
        'green, the queue of vehicles started to move forward, the AV started to move forward with the queue, '
        'and prior to crossing the intersection, the AV was struck from behind by an SUV. After impact the '
        'safety driver of the AV applied the brakes to disengage AD mode and then proceeded to find a safe spot '
        'to assess the incident by turning right onto [XXX]. The driver of the SUV followed the AV to a safe '
        'location to assess the incident and exchange contact information. There were no reported injuries, '
        'airbag deployments, or tow-aways between either party involved. The AV sustained minor damage to the '
        'rear of the vehicle including the rear bumper cover, rear bumper carrier, and a rear facing camera. The '
        'SUV damage was reported as scratches and dents to the front bumper cover. Both vehicles were able to '
        'safely drive away from the scene. VWGoA does not plan to investigate the incident any further as the '
        "facts and circumstances do not indicate any issue with the vehicle's performance."),
    'nhtsa-sgo-ads-30270-10557-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10557, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 1:09 PM CT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, Texas '
        'was in a collision involving a passenger car near [XXX] and [XXX]. The Waymo AV was preparing to make a '
        'right turn and merge into [XXX] from a roadway that was located south of [XXX]. While the Waymo AV '
        'remained stopped at a stop sign yielding to traffic, a passenger car traveling directly behind the '
        "Waymo AV made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 "
        'ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under '
        'Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10561-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10561, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April[XXX], 2025 at 10:41 PM ET a Waymo Autonomous Vehicle ("Waymo AV") operating in Atlanta, '
        'Georgia was in a collision involving a traffic control gate arm on [XXX] near [XXX]. The Waymo AV was '
        'traveling southbound on [XXX] and came to a stop behind a passenger car that had stopped for a closed '
        'traffic control gate arm. While the Waymo AV remained stopped, the gate arm rose to allow the passenger '
        'car to pass through. After the passenger car had passed through the gate, the Waymo AV began to proceed '
        'through the open gate when the gate arm lowered and made contact with the front of the Waymo AV. At the '
        "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained "
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8631-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8631,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2024 at 10:59 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Ari'
        'zona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling nort'
        'hwestbound on [XXX] and slowed to a stop in anticipation of turning right into a driveway immediatel'
        'y after the intersection with [XXX]. A passenger car traveling southeastbound on [XXX] made a U-turn'
        ' in the near-side crosswalk just behind and to the left of the Waymo AV as the AV was slowing, and t'
        'he front passenger side of the passenger car made contact with the rear driver side of the Waymo AV.'
        " At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles"
        ' sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-'
        '01. Waymo may supplement or correct its reporting with additional information as it may become avail'
        'able.'),
    'nhtsa-sgo-ads-30270-10598-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10598, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 7:34 AM CST a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, Texas '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was stopped facing east in '
        'the right turn lane on [XXX] for a red traffic light at the intersection with [XXX]. The Waymo AV began '
        'to slowly proceed forward and came to a stop to gain visibility of oncoming traffic traveling '
        'southbound on [XXX] in preparation for a right turn on red. A passenger car, which was initially '
        'stopped directly behind the Waymo AV, proceeded forward and the front of the passenger car made contact '
        "with the rear of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request '
        'No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10599-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10599, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:41 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Venice, '
        'California was in a collision involving a van on [XXX] near [XXX]. The Waymo AV was parked in-lane for '
        'a passenger drop-off facing southwest on [XXX] with hazard lights activated. A van that was stopped '
        'directly behind the Waymo AV began to maneuver around the stationary Waymo by crossing the yellow '
        'center line, entering the opposing lane of travel. As the van proceeded to the left of the stationary '
        'Waymo AV, the Waymo AV passenger opened the driver side rear door and the passenger side of the van '
        'made contact with the open driver side rear door of the Waymo AV. At the time of the impact, the Waymo '
        "AV's Level 4 ADS was engaged in autonomous mode. The passengers who were seated in the rear of the "
        'Waymo AV and the front passenger seat were not belted at the time of the collision, as they were likely '
        'preparing to exit the Waymo AV. Both vehicles sustained damage. Waymo is reporting this crash under '
        'Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10602-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10602, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 1:29 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a non-powered cord on [XXX] at [XXX]. The Waymo '
        'AV was traveling southbound on [XXX] when the front of the Waymo AV made contact with a cord that '
        'was draped across the roadway and attached to a plastic chair in the opposing lane. At the time of '
        "the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained "
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo '
        'may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10630-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10630, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 9:10 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'northbound on [XXX] and came to a stop, allowing for a passenger car to exit a parking lot on the east '
        'side of the roadway. As the passenger car turned left onto [XXX] and attempted to pass the Waymo AV, '
        'the driver side of the passenger car made contact with the rear driver side of the stationary Waymo AV. '
        "At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The passenger car "
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10639-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10639, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 7:41 AM MST a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Arizona '
        'was in a collision involving a passenger car on [XXX] at an off-ramp onto [XXX]. The Waymo AV was '
        'stopped in a queue of traffic facing north on an off-ramp of [XXX] at the T-intersection with [XXX] in '
        'the leftmost right turn lane waiting for eastbound traffic to clear before proceeding to merge right '
        'onto [XXX]. The Waymo AV began to proceed forward once the vehicle ahead made its turn, then came to a '
        'stop as it moved forward onto [XXX]. A passenger car traveling directly behind the Waymo AV approached '
        'the Waymo AV from behind, and the front of the passenger car made contact with the rear of the Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode, and a test "
        "driver was present in the driver's seating position. Both vehicles sustained damage. Waymo is reporting "
        'this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed '
        'away. Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'nhtsa-sgo-ads-30270-10640-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10640, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:47 PM MST a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, '
        'Arizona was in a collision involving an SUV in the West Parking Lot off of [XXX] at the [XXX]. The '
        'Waymo AV was parked facing south in a parking stall in the West Parking Lot off of [XXX}. The Waymo AV '
        'proceeded to reverse to exit the parking stall, and came to a stop to yield to an SUV that was stopped '
        'in-lane facing east to the left of the Waymo AV, at an intersection within the parking lot. As the '
        'Waymo AV was preparing to maneuver around the SUV, a second Waymo AV approached both vehicles from the '
        'south in the north-south travel lane of the parking lot and came to a stop in front of the SUV. The SUV '
        'reversed and the rear passenger side of the SUV made contact with the driver side of the Waymo AV. At '
        "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10649-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10649, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 8:48 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
        'southbound on a narrow portion of [XXX] and was slowing to a stop for a passenger drop-off when a '
        'passenger car traveling southbound on [XXX] began passing the Waymo AV. As the passenger car passed the '
        'Waymo AV, the passenger side of the passenger car made contact with the rear driver side of the Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10666-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10666, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 1:15 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was parked at '
        'the curb facing west following a passenger drop-off on [XXX]. While the Waymo AV remained stationary, a '
        'passenger car traveling westbound on [XXX] initially stopped behind the Waymo AV, then proceeded to '
        'pass to Waymo AV on the left, and the passenger side of the passenger car made contact with the rear '
        "driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10668-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10668, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 10:41 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a pickup truck on [XXX] at [XXX]. The Waymo AV was stopped '
        'facing north at a red light on [XXX] with the left turn signal activated, preparing to make an '
        'unprotected left turn onto [XXX]. A pickup truck traveling eastbound on [XXX] made a right turn onto '
        '[XXX] and made contact with a passenger car parked facing south at the curb near the intersection with '
        '[XXX]. As the pickup truck maneuvered away from the passenger car and continued to proceed southbound '
        'on [XXX], the driver side of the pickup truck then made contact with the rear driver side of the Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The pickup "
        'truck sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order '
        '2021-01. Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'nhtsa-sgo-ads-30270-10672-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10672, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 5:59 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los '
        'Angeles, California was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was '
        'traveling southwest bound on [XXX] when it slowed to a stop as it approached an SUV reversing in '
        'the roadway. The Waymo AV reversed to make room for the reversing SUV and came to a stop at the '
        'right side of the roadway with hazard lights activated. The SUV continued reversing on the left '
        'side of the roadway and the rear passenger side of the SUV made contact with the front driver side '
        "of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 '
        'of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10673-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10673, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2025 at 9:59 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving a box truck and trailer on [XXX] at [XXX]. The Waymo AV was '
        'traveling southeastbound on [XXX] in the leftmost lane when it stopped at the intersection of [XXX] to '
        'yield to a box truck hauling a trailer within the intersection. The heavy truck was facing southwest, '
        'apparently attempting a multi-point turn. The truck stopped and the Waymo AV began to pass the truck on '
        'the left. The truck began reversing as the Waymo AV was passing and the Waymo AV came to a stop to '
        'yield to the truck. While the Waymo AV remained stopped, the truck continued to reverse, and the rear '
        'passenger side of the trailer made contact with the front passenger side of the Waymo AV. At the time '
        "of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained "
        'damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because a '
        'vehicle involved was towed away. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10674-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10674, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2025 at 11:36 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona '
        'was in a collision involving a wheel and tire on [XXX] near [XXX]. The Waymo AV was traveling '
        'northbound on [XXX] in the middle lane when the left front wheel from an SUV traveling in the right '
        "most lane of [XXX] separated from the SUV and rolled into the Waymo AV's lane of travel. The front "
        'driver side of the Waymo AV made contact with the wheel and tire. At the time of the impact, the Waymo '
        "AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this "
        'crash under Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10684-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10684, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 11:14 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Beverly Hills, '
        'California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was traveling '
        'northbound on a narrow portion of [XXX] with vehicles parked at both curbs when it came to a stop '
        'yielding to a pickup truck traveling southbound on [XXX]. As the pickup truck passed the stationary '
        'Waymo AV, the rear driver side of the pickup truck made contact with the rear driver side of the Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10685-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10685, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 10:25 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was traveling '
        'southeastbound on [XXX] and came to a stop in a queue of traffic for a red light at the intersection at '
        '[XXX]. An SUV traveling southeastbound on [XXX] approached the Waymo AV from behind, and the front of '
        'the SUV made contact with the rear of the stationary Waymo AV. At the time of the impact, the Waymo '
        "AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this "
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10695-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10695, version '
        '1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2025 at 8:50 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Paradise Valley, '
        'Arizona was in a collision involving an animal and subsequently an SUV on [XXX] at [XXX]. The Waymo AV '
        'was traveling southbound on [XXX] in the leftmost lane, proceeding through a green light at the '
        'intersection with [XXX]. As the Waymo AV exited the intersection, a cat crossed [XXX] from the east '
        "side of the street, and began to enter the Waymo AV's lane of travel. As the Waymo AV braked, the front "
        'of the Waymo AV made contact with the cat, which subsequently ran away, and the Waymo AV came to a '
        'stop. The front of an SUV traveling directly behind the Waymo AV then made contact with the right rear '
        'of the stationary Waymo AV. A passenger car then braked to a stop behind the Waymo and to the left of '
        'the SUV. A second passenger car then made contact with the SUV and the first passenger car. At the time '
        "of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. All involved vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away and because of airbag deployment. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10725-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10725, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 2:42 AM CT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, Texas '
        'was in a collision involving a pickup truck in a parking lot off of [XXX] near [XXX]. The Waymo AV was '
        'stopped facing northwest with hazard lights activated in a narrow parking lot off of [XXX] for a '
        'passenger pick-up. A pickup truck traveling southeast in the parking lot began to maneuver past the '
        'Waymo AV on the right. As the pickup truck passed by the stationary Waymo AV, the passenger side of the '
        'pickup truck made contact with the rear passenger side of the Waymo AV. At the time of the impact, the '
        "Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Both of the "
        'passengers, who were seated in the rear of the Waymo AV, were not belted at the time of the collision, '
        'having just entered the Waymo AV. Waymo is reporting this crash under Request No. 2 of Standing General '
        'Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'nhtsa-sgo-ads-30270-10726-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10726, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 9:07 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was traveling eastbound '
        'on [XXX] and stopped in the dedicated left turn lane, preparing to make an unprotected left turn onto '
        '[XXX]. As the Waymo AV remained stopped, an SUV that was traveling westbound on [XXX] in the middle '
        'shared turn lane, directly in front of the Waymo AV, maneuvered from the middle lane to the second from '
        'the left lane and the driver side of the SUV made contact with the rear driver side of the Waymo AV. At '
        "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV sustained "
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10742-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10742, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 3:29 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'CA was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was traveling '
        'northbound on [XXX] in the rightmost lane and slowed to a stop for an SUV that was parallel parking in '
        'front of the Waymo AV. While the Waymo AV was stopped, a pickup truck traveling directly behind the '
        'Waymo AV approached the Waymo AV from behind, and the front of the pickup truck made contact with the '
        "rear of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The pickup truck sustained damage. Waymo is reporting this crash under Request No. 2 '
        'of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10756-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10756, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 1:45 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was traveling '
        'eastbound on [XXX] when it approached a vehicle stopped in-lane. Another vehicle was stopped in-lane on '
        'the westbound side of [XXX], causing east bound vehicles to cross into the eastbound lane to proceed. '
        'As the Waymo AV passed to the left of the eastbound stationary vehicle, an SUV traveling westbound '
        'passed the stationary westbound vehicle and approached the Waymo AV and the Waymo AV came to a stop to '
        'yield to the oncoming SUV. While the Waymo AV remained stopped, the SUV proceeded forward and the front '
        'of the SUV made contact with the front of the Waymo AV. The Waymo AV then reversed and the SUV '
        'proceeded forward to make contact with the front of the Waymo AV a second time. After the Waymo AV '
        'finished reversing and stopped to the right side of the street, the SUV proceeded forward directly '
        "towards the Waymo AV's eastbound lane, and the front of the SUV made contact with the front of the "
        "Waymo AV a third time. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
        'mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of Standing '
        'General Order 2021-01. Waymo may supplement or correct its reporting with additional information as it '
        'may become available.'),
    'nhtsa-sgo-ads-30270-10757-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10757, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 11:53 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was traveling south on '
        '[XXX], and came to a stop behind a box truck that was stopped in-lane. The Waymo AV began to proceed '
        'around the left of the stopped box truck and came to a stop, yielding to an SUV traveling northbound on '
        '[XXX]. As the SUV passed by the stationary Waymo AV, the front driver side of the SUV made contact with '
        "the front driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request '
        'No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-10776-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10776, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2025 at 10:38 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a heavy truck on [XXX] near [XXX]. The Waymo AV was traveling '
        'westbound on [XXX]. The heavy truck traveling eastbound on [XXX] began maneuvering left into the path '
        'of the Waymo AV and the Waymo AV came to a stop. The truck continued and the front driver side of the '
        'heavy truck made contact with the front driver side of the Waymo AV. The heavy truck then reversed and '
        'proceeded eastbound. As the heavy truck passed the stationary Waymo AV, it made contact with the driver '
        "side of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 1 of '
        'Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-3057-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-3057, '
        'version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The content of this report is unchanged from the initial report submitted on May [XXX], 2022 [Report ID '
        '# 30270-3057-1]. On May [XXX], 2022 at 2:30 AM PST a Waymo Autonomous Vehicle ("Waymo AV") operating in '
        'Phoenix, Arizona was in a collision involving a passenger vehicle on [XXX] at the [XXX] onramp. While '
        'the Waymo AV was stopped at a red light on southbound [XXX] in the rightmost through lane, a passenger '
        'vehicle approached the Waymo AV from behind and the right front of the passenger vehicle made contact '
        "with the left rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged "
        "in autonomous mode and a test driver was present (in the driver's seating position). Both vehicles "
        'sustained major damage. The driver of the other vehicle was transported from the scene to a hospital '
        'for medical treatment. Waymo is reporting this crash under Request No. 1 of Standing General Order '
        '2021-01 because a vehicle involved was towed away, the crash resulted in airbag deployment, and the '
        'driver of the other vehicle was transported from the scene to a hospital for medical treatment. Waymo '
        'may supplement or correct its reporting with additional information as it may become available. This '
        'report was submitted from the Pacific time zone on the required date.'),
    'nhtsa-sgo-ads-30270-3786-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-3786,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On September [XXX], 2022 at 1:13 PM PST a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving two passenger cars on [XXX] at [XXX]. The Waymo AV was stopped '
        'in traffic at a red light facing West on [XXX]. The passenger car immediately behind the Waymo AV '
        'slowed and came to a near stop when a second passenger car approaching from behind made contact with'
        ' the rear of the first passenger car, causing that car to make contact with the rear of the Waymo '
        'AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode, and a test '
        'driver was present (in the drivers seating position). All three vehicles sustained damage. Waymo is '
        'reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle '
        'involved was towed away, because of airbag deployment, and because an occupant in one of the '
        'passenger vehicles was transported for medical attention. Waymo may supplement or correct its '
        'reporting with additional information as it may become available. This report was submitted from the'
        ' Pacific time zone on the required date.'),
    'nhtsa-sgo-ads-30270-5896-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-5896, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2023 at 6:13 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Chandler, Arizona '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling northbound '
        'on [XXX] and just passed [XXX] when an oncoming passenger car crossed into the Waymo AVs lane, toward '
        'the Waymo AV. The Waymo AV then stopped as the passenger vehicle continued to approach. The passenger '
        'vehicle then made contact with the front of the Waymo AV, and then made contact with the side of the '
        'Waymo AV as it left the scene. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in '
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 of '
        'Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-6131-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-6131, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2023 at 9:02 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, Arizona '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was parallel parked along '
        'the right-hand curb on eastbound [XXX] when a passenger car reversed out of a driveway across the '
        'street from the Waymo AV and made contact with the driver side rear bumper of the Waymo AV. At the time '
        'of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained '
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-7719-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7719, '
        'version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'This report is mean to correct monthly report 30270-7719-1 (submitted 05/15/2024), which '
        'erroneously marked the "Incident Date" and "Notice Received Date" as 05/06/2024 when the correct '
        'date for both fields is 04/[XXX]/2024. On April [XXX], 2024 at 12:26 PM PT a Waymo Autonomous '
        'Vehicle (Waymo AV) operating in San Francisco, California was in a collision involving a passenger '
        'car on [XXX] at [XXX]. The Waymo AV was traveling southbound on [XXX] at the intersection with '
        '[XXX]. As the Waymo AV approached the intersection, it slowed to a stop with its left turn signal '
        'activated before the intersection, preparing to make an unprotected left turn onto eastbound [XXX]. '
        'While the Waymo AV was yielding to traffic in the intersection, a passenger car traveling directly '
        'behind the Waymo AV made contact with the rear of the Waymo AV. At the time of the impact, the '
        'Waymo AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is '
        'reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-7724-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7724, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2024 at 8:35 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, '
        'California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was traveling '
        'southbound on [XXX] when it approached a stopped pickup truck with a vehicle-mounted arrow board with '
        'an arrow pointing to the right illuminated. The pickup truck was stopped in the leftmost lane, which is '
        'the only general-purpose travel lane. The Waymo AV began changing lanes into the right lane, which is a '
        'dedicated bus lane, to pass the stopped pickup truck. The pickup truck then began proceeding straight '
        'while the Waymo AV was behind the pickup truck, and the Waymo AV started to return to the left lane '
        'behind the pickup truck. The pickup truck came to a stop, and the Waymo AV also came to a stop. The '
        'pickup truck then began reversing, and the rear of the pickup truck made contact with the front driver '
        'side bumper of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in '
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-7729-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7729, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2024 at 11:07 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Santa Monica, '
        'California was in a collision involving a chain in a parking lot at [XXX]. The Waymo AV was traveling '
        'northwest on [XXX] when it made a left turn into a parking lot at [XXX]. As the Waymo AV was turning '
        'into the section of the parking lot directly to its left, the Waymo AV made contact with a hanging '
        'chain separating a section of the parking lot. At the time of the impact, the Waymo AVs Level 4 ADS was '
        'engaged in autonomous mode. The Waymo AV and the chain sustained damage. Waymo is reporting this crash '
        'under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting '
        'with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-7734-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7734, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 9:34 PM MT Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling east on '
        '[XXX] and came to a stop at a red light at the intersection with [XXX] to prepare for a right turn. The '
        'Waymo AV yielded to cross traffic traveling south on [XXX] and then initiated a right turn when a '
        'passenger car traveling north on [XXX] initiated a U-turn across the intended path of the Waymo AV. The '
        'Waymo AV slowed to yield to the U-turning passenger car and had begun to accelerate again to complete '
        'the right turn when the front of another passenger car which was following behind the Waymo AV made '
        "contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request '
        'No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-7935-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7935, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 10:36 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a van on [XXX] at [XXX]. The Waymo AV was stopped for a '
        'passenger pickup with the front of the Waymo AV in a parking area and its rear in the travel lane on '
        '[XXX] near the intersection with [XXX]. A van traveling west on [XXX] passed the Waymo AV on the left '
        'side. The right side of the van came in contact with the rear left side of the Waymo AV. At the time of '
        "the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. "
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-7936-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7936, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 8:25 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Arizona '
        'was in a collision involving a chain at the entrance of a parking lot at Arizona State University on '
        '[XXX] near [XXX]. The Waymo AV was traveling north on [XXX] when it made a left turn into a parking lot '
        'near [XXX]. As the Waymo AV was entering the parking lot, it made contact with a chain hanging at the '
        "entrance of the parking lot. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The chain sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-8039-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8039, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2024, at 12:59 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in [XXX], '
        'California was involved in an alleged collision with a non-motorist (cyclist) at a parking garage exit '
        'on [XXX] between [XXX] and [XXX]. The Waymo AV was exiting a parking garage onto [XXX], between [XXX] '
        'and [XXX]. As the Waymo AV approached the garage exit, it stopped for a cyclist who was approaching '
        'from the left. The Waymo AV remained stationary as the cyclist passed in front of the vehicle, slowed, '
        'and appeared to begin to dismount. The cyclist then reached out a hand and made contact with the front '
        'passenger side of the stationary Waymo AV, backed the bicycle up slightly, dropped the bicycle, then '
        "fell to the ground. At the time of the possible impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode, and a test driver was present. The cyclist received medical attention at the scene and '
        'was reportedly transported to a hospital by local emergency services. The Waymo AV did not sustain any '
        'damage. Even though this event may involve intentional contact by the bicyclist with a stationary Waymo '
        'AV and the occurrence of actual impact between the Waymo AV and the cycle is not clear, Waymo is '
        'reporting this event as a crash under Request No. 1 of Standing General Order 2021-01 because a media '
        'report included an allegation of a crash and because a vulnerable road user (cyclist) influenced the '
        'driving task of a vehicle involved and reportedly was transported to a hospital for medical treatment '
        'as a result of the event. Waymo may supplement or correct its reporting with additional information as '
        'it may become available.'),
    'nhtsa-sgo-ads-30270-8061-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8061, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2024 at 8:43 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in [XXX], '
        'California was in a collision involving a passenger car on [XXX]. The Waymo AV was traveling east on '
        '[XXX]. As the AV approached the all-way stop sign at [XXX], it detected a vehicle traveling west on '
        '[XXX] and crossing into the opposing lane (the lane in which the AV was traveling). The passenger car '
        'entered the intersection in the opposing lane without slowing. The Waymo AV slowed down and maneuvered '
        'towards the right side of the eastbound lane as the front of the passenger car, still moving in the '
        'wrong direction in the eastbound lane, made contact with the front driver side corner of the Waymo AV. '
        "At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away and because of airbag deployment. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-669-8496-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 669-8496, v'
        'ersion 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        "In conjunction with Motional's filing of the subject incident, and according to statement(s) provide"
        "d in Motional's incident report: A Motional AV with VIN PFDKB4AE6RF[XXX] was operating in autonomous"
        ' mode in Las Vegas, Nevada at approximately 1PM PT, with a safety driver at the wheel, an engineer i'
        'n the front passenger seat, and two other employees in the rear seats. The AV was in a right-turn la'
        'ne, turning onto [XXX] from [XXX]. The AV stopped at a yield sign in the right-turn only lane before'
        ' merging onto [XXX] and a silver Toyota rear-ended the AV at approximately 15 MPH. There were three '
        'occupants of the silver Toyota, one in the front seat and two in the back, with one verbally reporti'
        'ng an injury to the face area. An ambulance was traveling on [XXX]. at the time of the incident and '
        'stopped at the scene. The ambulance transported the complaining occupant of the silver Toyota and an'
        "other occupant (believed to the individual's sister) rode in the ambulance. It is unknown where thes"
        'e individuals were taken. No injuries were reported from the occupants in the AV. Both vehicles were'
        ' damaged and required towing from the scene. No airbags were deployed in either vehicle. Las Vegas M'
        'etro Police were called to the scene. It is unknown if the other driver was cited. A police report w'
        'ill be supplied when available. 9/16/2024 Update: No new information available at this time.'),
    'nhtsa-sgo-ads-30270-8875-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8875,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On September [XXX], 2024 at 6:17 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Franci'
        'sco, California was in a collision involving a van on [XXX] near [XXX]. The Waymo AV was stopped in '
        'traffic in the dedicated right turn lane of southwestbound [XXX]. While the Wamo AV remained stopped'
        ', a van traveling behind the Waymo AV partially entered the left adjacent lane to maneuver around th'
        'e Waymo AV. As the van was passing the stopped Waymo AV, the front passenger side of the van made co'
        'ntact with the rear driver side of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 AD'
        'S was engaged in autonomous mode. The van sustained damage. Waymo is reporting this crash under Requ'
        'est No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with addi'
        'tional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8121-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8121, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 10:52 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], California '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling northeast on '
        '[XXX] in the center lane of three lanes when it activated its left turn signal. Simultaneously, a '
        'passenger car that was traveling behind the Waymo AV at a high rate of speed began to change lanes from '
        'the rightmost lane to the leftmost lane. As the Waymo AV entered the leftmost lane, the passenger car '
        'passed the Waymo AV in the leftmost lane of southwestbound [XXX]. The passenger side of the passenger '
        'car then made contact with the driver side of the Waymo AV. At the time of the impact, the Waymo AVs '
        'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage and the passenger car left '
        'the scene. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo '
        'may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8130-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8130, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 1:33 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], California '
        'was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling southwest '
        'on [XXX] in the dedicated left turn lane. The Waymo activated its turn signal and began a lane change '
        'into the right thru lane where there was a gap in a slow-moving traffic stack. The passenger car that '
        'was behind the gap in the traffic stack accelerated as the Waymo AV began merging and the front driver '
        'side corner of the passenger car made contact with the rear passenger side corner of the Waymo AV. At '
        'the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles '
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8141-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8141, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 6:05 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], California '
        'was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was traveling east on '
        '[XXX] at a location where the width of the roadway is narrow, and there were lines of parked vehicles '
        'on both sides of the roadway. A pickup truck traveling west on [XXX] approached the Waymo AV and the '
        'Waymo AV shifted to the right side of the road and came to a stop to allow the pickup truck to pass. As '
        'the pickup truck passed the Waymo AV, the rear driver side fender of the pickup truck made contact with '
        'the rear driver side corner of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was '
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request '
        'No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-8150-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8150, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 11:39 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], California '
        'was in a collision involving an SUV near [XXX]. The Waymo AV was stopped curbside for a pickup facing '
        'north on the east side of [XXX] when an SUV that had been stopped partially in-lane behind the Waymo AV '
        'passed the Waymo AV on the left . The passenger side rear door of the SUV made contact with the rear '
        'driver side corner of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in '
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-8152-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8152, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 8:15 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], '
        'California was in a collision involving a portable metal barrier on [XXX] at [XXX]. The Waymo AV '
        'was traveling southeast on [XXX] at a low rate of speed when the front of the Waymo AV made contact '
        'with a portable metal barrier at the intersection with [XXX]. As the Waymo AV made a right turn '
        'onto southwestbound {XXX], it pushed the barrier along with it and the rightmost edge of the '
        'barrier made contact with the rear driver side of a postal van parked at the curb of southwestbound '
        '[XXX]. As the Waymo AV began to slow to initiate a pull over (still pushing the barrier), the '
        'rightmost edge of the barrier made contact with the driver side of two other postal vans and two '
        'passenger cars that were also parked at the curb of southwestbound [XXX]. The Waymo AV continued to '
        'push the barrier as it completed the pullover, coming to a stop on the right side of southwestbound '
        '[XXX]. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The '
        'metal barrier and all vehicles mentioned sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01.Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9330-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9330, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 7:47 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was stationary '
        'in the left turn lane of [XXX] preparing for an unprotected left turn onto southwestbound [XXX] when a '
        'passenger car traveling southeast in the center lane of South [XXX] entered the intersection and '
        'departed its lane into the path of left-turning traffic from northwestbound South [XXX]. The front '
        'driver side of the passenger car then made contact with the front driver side of the stationary Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9333-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9333, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 10:19 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a mini coach bus on [XXX] at [XXX]. The Waymo AV was '
        'stopped facing south in the rightmost lane of [XXX] after a passenger dropoff when a mini coach bus '
        'initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]. As the bus '
        'passed the stopped Waymo AV, the passenger side of the bus made contact with the rear driver side of '
        "the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. "
        'Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General '
        'Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or correct its reporting '
        'with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9347-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9347, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 3:29 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los '
        'Angeles, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV '
        'was traveling east on [XXX] and came to a stop for a red traffic light at the intersection with '
        '[XXX]. While the Waymo AV remained stopped, a passenger car approached the Waymo AV from behind and '
        'the front of the passenger car made contact with the rear of the Waymo AV. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. "
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9350-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9350, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 8:03 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a SUV on [XXX] near [XXX]. The Waymo AV was parked '
        'at the curb in the northbound direction of [XXX] when an SUV began to parallel park behind the Waymo '
        'AV. While parking, the SUV moved forward from the curb into the roadway, maneuvering to the left of the '
        'Waymo AV, and the passenger side of the SUV made contact with the rear driver side of the stationary '
        "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV "
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9355-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9355, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 12:57 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, '
        'Arizona was in a collision with a piece of debris on [XXX] near [XXX]. The Waymo AV was traveling '
        'westbound on [XXX] in the right lane when the front passenger side of the Waymo AV made contact '
        "with a piece of debris that was in the lane of travel. At the time of the impact, the Waymo AV's "
        'Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this '
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9371-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9371, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 2:33 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'eastbound on [XXX] and came to a stop for a red traffic light in the dedicated left turn lane, '
        'preparing to make a left turn onto northbound [XXX]. A passenger car approached the stationary Waymo AV '
        'from behind in the adjacent straight lane, and crossed into the lane that the Waymo AV was occupying. '
        'The front driver side of the passenger car made contact with the rear passenger side of the stationary '
        "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both "
        'vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order '
        '2021-01. Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'nhtsa-sgo-ads-30270-9376-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9376, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 10:36 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was alleged to have contributed to a collision between an SUV and a concrete '
        'median curb on [XXX] at [XXX]. The Waymo AV was traveling southbound on [XXX] in the right of two '
        'travel lanes with its left turn signal activated, and traversed through the intersection with [XXX] '
        'with an SUV following slightly behind and to the left of the Waymo AV in the adjacent travel lane. As '
        'the Waymo AV exited the intersection with its left turn signal still activated, it slowed and moved '
        'slightly to the left within its lane, preparing to change lanes due to a stopped truck ahead within the '
        'right lane. As the SUV in the left lane was passing the Waymo AV, it maneuvered to the left in its '
        'lane, and the driver side made contact with the center concrete median curb. At the time of the impact, '
        "the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV sustained a flat tire, and the "
        'driver alleged an injury. Waymo is reporting this crash under Request No. 2 of Standing General Order '
        '2021-01. Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'nhtsa-sgo-ads-30270-9408-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9408, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 1:54 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV '
        'was traveling west on [XXX] when it came to a stop, yielding to stopped traffic ahead. While the '
        'Waymo AV remained stationary, a passenger car that was traveling behind the Waymo AV began to lane '
        'change right. As it did so, the front driver side of the passenger car made contact with the rear '
        "passenger side of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9409-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9409, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On Saturday, November [XXX], 2024 at 1:27 AM MST, a Waymo Autonomous Vehicle ("Waymo AV") operating in '
        'Scottsdale, Arizona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was '
        'traveling north on [XXX] when it encountered a queue of double-parked vehicles in the northbound lane. '
        'The Waymo AV began passing the double-parked vehicles on the left, but as it did so the queue of '
        'double-parked vehicles began to proceed. The Waymo AV began to merge back into the northbound lane, but '
        'a vehicle in the queue then double-parked again before the Waymo AV could fully merge back into the '
        'northbound lane. The Waymo AV then began reversing to make space for southbound traffic but came to a '
        'stop before completing its reversing maneuver to yield to traffic approaching the Waymo AV from the '
        'rear. A passenger car traveling south on [XXX] then crossed the double yellow line to pass the Waymo AV '
        'in the northbound lane. As it did so, the rear passenger side of the passenger car made contact with '
        'the rear driver side of the Waymo AV. The passenger was not belted at the time, likely because the AV '
        "had just departed its pickup location. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. The passenger car sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9414-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9414, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 11:07 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was '
        'parked at the curb in the northwest direction of [XXX]. A pickup truck began to parallel park behind '
        'the Waymo AV, and the front bumper of the pickup truck made contact with the rear bumper of the Waymo '
        'AV. After this initial contact, the pickup truck reversed, then maneuvered away from the curb towards '
        'the lane of travel, and the front passenger side of the pick up truck made contact with the rear driver '
        "side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
        'mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of Standing '
        'General Order 2021-01. Waymo may supplement or correct its reporting with additional information as it '
        'may become available.'),
    'nhtsa-sgo-ads-30270-9431-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9431, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 2:21 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Los Angeles, '
        'California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was '
        'traveling northwest in the leftmost lane of a two-lane section of [XXX] behind a pickup truck '
        'traveling in the same direction. As the pickup truck approached the intersection with [XXX], it '
        'maneuvered into the center left turn lane. The pickup truck continued to travel in the center left '
        'turn lane, which, after crossing the intersection, became the leftmost dedicated left turn lane for '
        'oncoming traffic. As the Waymo AV was passing the pickup truck on the right, the pickup truck began '
        'to maneuver out of its lane and re-enter the leftmost lane of northwestbound [XXX]. The passenger '
        'side of the pickup truck made contact with the driver side of the Waymo AV. At the time of the '
        'impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. '
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9433-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9433, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 6:16 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San '
        'Francisco, California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was '
        'stopped in traffic for a red light on northbound [XXX] when an SUV approached the Waymo AV from '
        'behind. The front of the SUV made contact with the rear of the Waymo AV. At the time of the impact, '
        'the Waymo AVs Level 4 ADS was engaged in autonomous mode, and only one of the two passengers was '
        'wearing a seatbelt. The SUV sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-9435-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9435, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 10:29 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Los '
        'Angeles, California was in a collision involving an SUV on [XXX] near [XXX]. As the Waymo AV was '
        'parked at the curb on the right side of the street facing north on [XXX], an SUV reversed out of a '
        'driveway on the left side of the street. The rear of the SUV made contact with the rear driver side '
        'of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous '
        'mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of Standing '
        'General Order 2021-01. Waymo may supplement or correct its reporting with additional information as '
        'it may become available.'),
    'nhtsa-sgo-ads-30270-9436-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9436, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 12:56 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Beverly '
        'Hills, California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was stopped on '
        'the right side of southwestbound [XXX] for a passenger pick-up when an SUV traveling in the rightmost '
        'lane of southwestbound [XXX] passed the Waymo AV. As the SUV passed the stopped Waymo AV, the passenger '
        'side of the SUV made contact with the driver side of the Waymo AV. At the time of the impact, the Waymo '
        'AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this '
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9486-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9486, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 12:28 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV '
        'was traveling on northbound [XXX] and slowed down to a stop for a queue of traffic. A passenger car '
        'approached the Waymo AV from behind,and the front of the passenger car made contact with the rear of '
        'the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both '
        'vehicles sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order '
        '2021-01 because a vehicle involved was towed away. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9507-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9507, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 4:07 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a pick-up truck on [XXX] near [XXX]. The Waymo AV '
        'was traveling southbound in the center lane of [XXX] and slowed down to a stop for a queue of traffic. '
        'A pick-up truck traveling in the right most lane and next to the Waymo AV began to change lanes into '
        'the center lane, and the driver side of the pickup truck made contact with the front passenger front '
        'side of the stationary Waymo AV. After this initial contact, the pick-up truck maneuvered to the front '
        'of the Waymo AV, came to a stop directly in front of the Waymo AV, and after a few minutes, the pickup '
        'truck reversed, and the rear of the pickup truck made contact with the front of the stationary Waymo '
        'AV. The Waymo AV remained stopped in lane due to the initial contact the driver of the pickup truck was '
        'in and out of their vehicle until leaving the scene. After approximately 4 minutes, the pick-up truck '
        'returned, traveling southbound in the right lane of [XXX], and the driver side of the pickup truck made '
        'contact with the passenger side of the still stationary Waymo AV. At the time of each point of impact, '
        "the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is "
        'reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle involved '
        'was towed away. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'nhtsa-sgo-ads-30270-9540-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9540, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December[XXX], 2024 at 8:21 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV '
        'had pulled up to the curb facing northbound on [XXX] for a requested passenger pickup. While awaiting '
        'the passenger, the Waymo AV was partially obstructing access to a residential garage and a passenger '
        'car began reversing out of the garage and the rear driver side of the passenger car made contact with '
        "the rear passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request '
        'No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-9544-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9544, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 6:09 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was travelling southbound '
        'on the single lane on [XXX], preparing to enter the dedicated left turn lane at the intersection with '
        '[XXX], when an SUV was exiting a shopping center driveway making a right turn onto southbound [XXX]. As '
        'the SUV turned, the front driver side of the SUV made contact with the passenger side of the Waymo AV. '
        'At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles '
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9545-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9545, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 6:27 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] at Interstate [XXX] onramp. '
        'The Waymo AV was traveling eastbound on [XXX] when it came to a stop within the intersection with '
        'Interstate [XXX] onramp due to a queue of traffic on the other side of the intersection. The rear of '
        'the Waymo AV partially occupied the lane connecting westbound [XXX] to the Interstate [XXX] onramp. A '
        'passenger car was travelling westbound on [XXX], and began making a left turn onto the Interstate [XXX] '
        'onramp when the driver side of the passenger car made contact with the rear driver side of the Waymo '
        "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV "
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. '
        'Waymo may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9552-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9552, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 8:34 PM CT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, Texas '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling southbound '
        'in the left hand turn lane on [XXX] and stopped in a queue of traffic at a red light. A passenger car '
        'traveling directly in front of the Waymo AV started to reverse backwards towards the Waymo AV. The '
        'Waymo AV began to reverse to avoid the passenger car, then slowed to a stop. The passenger car '
        'continued to reverse and the rear of the passenger car made contact with the front of the Waymo AV. At '
        "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV "
        'sustained damage Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9631-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9631, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 2:55 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'north on [XXX] when it approached the intersection with [XXX]. As the Waymo AV approached the '
        'intersection, it slowed to yield to a pedestrian who was traveling south on the sidewalk of [XXX] and '
        'had just entered the intersection to cross [XXX]. As the Waymo AV continued to slow, a passenger car '
        'traveling directly behind the Waymo AV approached the Waymo AV from behind. The front of the passenger '
        'car made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS '
        'was engaged in autonomous mode. Both vehicles sustained damage. The passenger in the Waymo AV reported '
        'a minor injury. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vulnerable road user influenced the driving task of a vehicle involved and because vehicles '
        'involved were towed away. Waymo may supplement or correct its reporting with additional information as '
        'it may become available.'),
    'nhtsa-sgo-ads-30270-9654-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9654, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 3:32 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a cyclist on [XXX] at [XXX]. The Waymo AV was '
        'traveling northbound on [XXX] in the rightmost lane, and came to a stop for a red light at the '
        'intersection with [XXX]. While the Waymo AV remained stopped at the intersection, a cyclist traveling '
        'southbound against traffic proceeded through the intersection, passing the Waymo AV on the left, and '
        'the cyclist made contact with the driver side of the stationary Waymo AV. At the time of the impact, '
        "the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is "
        'reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vulnerable road '
        'user was involved. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'nhtsa-sgo-ads-30291-7677-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30291-7677, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At approximately 12pm CST, May [XXX], 2024, a passenger vehicle rear-ended a Nuro Prius operating in '
        'autonomous mode at the intersection of [XXX] and [XXX] in Houston, Texas. The Nuro Prius was coming to '
        'a stop as the traffic signal changed from yellow to red. Shortly after the light turned red, a '
        'passenger vehicle rear-ended the Nuro Prius. No injuries were reported at the scene and law enforcement '
        'were not involved. Both vehicles sustained minimal damage.'),
    'nhtsa-sgo-ads-30291-7981-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30291-7981, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At approximately 5:10pm CDT, a passenger vehicle collided with a Nuro Prius operating in manual mode in '
        'Houston, Texas. Prior to the collision, the Nuro Prius operating autonomously came to a stop at the '
        'intersection of [XXX] and [XXX]. The Nuro operator disengaged autonomy, switched to manual, and '
        'proceeded to make a left turn. A passenger vehicle collided with the Nuro Prius before the driver '
        'completed the turn. No injuries were reported. Both vehicles sustained damage. Law enforcement was not '
        'involved.'),
    'nhtsa-sgo-ads-30310-3698-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30310-3698, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Prior to the crash, on August [XXX], 2022 autonomous shuttle (MNCAV2, V005) for the Med City Mover was '
        'travelling southbound on [XXX]. in autonomous ADS mode. The vehicle was functioning normally prior to '
        'the event in autonomous mode. At 16:23 CT, the shuttle entered the intersection of [XXX] and [XXX]. The '
        'shuttle experienced an unknown e-stop. The vehicle behind the shuttle was following closely and '
        'attempting to pass the shuttle at this time and hit the rear left corner of the shuttle. No injuries '
        'reported to the two passengers on-board the shuttle or the operator or other vehicles two passengers. '
        'Seatbelts were used by the shuttle passengers at the time of the incident. 911 was called and the '
        'Minnesota Department of Public Safety was dispatched to file a report. Details of the event can be '
        'provided in video format, a police report and an operator summary. The GPX coordinates above are '
        'approximate at the time of the e-stop. The shuttle had experienced an unknown e-stop at 15:59 CT on '
        '[XXX] (no passengers).'),
    'nhtsa-sgo-ads-30413-10763-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-10763, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Manual control was initiated by a May autonomous shuttle operator for a right turn onto [XXX] in '
        'Atlanta, GA. Autonomous mode was then engaged. The autonomous system executed a stop due to a '
        'narrow passage obstructed by parked vehicles on both sides of the roadway and an approaching '
        'vehicle. Following the departure of the first vehicle and the next oncoming vehicle 80m away, the '
        'Autonomous Vehicle Operator (AVO) disengages and proceeds in manual. The AVO overcorrects to the '
        "right slightly and a minor contact with the parked car's mirror occurs. Our team looked at the "
        'incident and determined that this event was caused by human error - no autonomy software defects '
        'led to this incident.'),
    'nhtsa-sgo-ads-30413-10764-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-10764, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A May autonomous shuttle (ego) was stopped at a traffic light in autonomous mode. A vehicle approaching '
        'from behind coasted into the ego vehicle. Our system responded with a software Health Drop, which '
        'immediately took the ego out of autonomous mode (for safety). Minor damage was reported to our rear '
        'sensor and bumper.'),
    'nhtsa-sgo-ads-30413-4170-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-4170, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Operator was approaching stop sign at the intersection of [XXX] westbound and [XXX] northbound, '
        'which is a planned disengagement (this unprotected turn is outside of our ODD). If left in '
        'autonomy, the vehicle would have come to a full stop before the stop line and remained stopped '
        'until the operator took over. 6 seconds prior to incident, operator took the vehicle over manually '
        'before it could have stopped in autonomy. Operator moved the vehicle manually passed the stop line, '
        "colliding with a bicyclist's back tire. No injuries reported from the bicyclist or the operator and "
        'no damage to the vehicle or bicycle.'),
    'nhtsa-sgo-ads-30413-6032-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-6032, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The May vehicle came to a gentle stop at the railroad crossing (about -0.8 m/s2 deceleration) as '
        'designed, but the agent behind did not come to a stop and made contact with the AV. The May shuttle '
        'behaved as expected and slowed down to a stop in a safe manner. The collision was unavoidable from the '
        'shuttle side.'),
    'nhtsa-sgo-ads-30413-7880-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-7880, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'While in traffic and stopped at 0mph in autonomy, a motorized scooter riding between the 2 lanes of '
        "traffic clipped the May Mobility vehicle's mirror with their own mirror. The scooter proceeded along "
        'its way, seemingly unaware of the mirror clip.'),
    'nhtsa-sgo-ads-30530-7892-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30530-7892, version 1, '
        'column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024, at 3:09 AM CDT, an Aurora truck struck a small animal on [XXX] near Corsicana, TX. '
        'Aurora disengaged autonomy before impact. Aurora vehicle operators were not injured. The Aurora truck '
        'sustained minor damage to its front bumper, and the truck continued to its final destination in Palmer, '
        'TX.'),
    'nhtsa-sgo-ads-30590-3431-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30590-3431, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Subject vehicle was on a testing mission in Mountain View, CA. The vehicle was traveling North-bound on '
        "[XXX] operated by the vehicle's Level 4 Automated Driving System and supervised by a safety driver in "
        "the driver's designated seating position, and with a safety operator in the front passenger seating "
        'position. Subject vehicle approached a red light to make a right turn East-bound onto [XXX]. The safety '
        'operator suggested that the safety driver disengage the ADS and make the turn in manual mode because '
        'the vehicle was hesitant in approaching the intersection. The safety driver disengaged the ADS, and, '
        'approximately 250ms later, subject vehicle was lightly struck from behind by a white Mazda3. Having '
        'seen debris on the roadway, the driver and operator believed they had run over a rock and did not '
        'realize they were hit by the vehicle. After concluding the mission, the driver and operator found '
        'damage to a sensor during an inspection. A subsequent review of video led to discovery of the crash. No '
        'injuries were reported, and law enforcement was not called to the scene. In addition to telematics and '
        "video, we also have photographs of the vehicle's damaged sensor."),
    'nhtsa-sgo-ads-30610-3719-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-3719, '
        'version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle in autonomy was proceeding at approximately 2mph towards an exit of a private hotel '
        'driveway in Las Vegas, Nevada when it was struck on its right front fender by two individuals involved '
        'in an altercation who had darted out from the side of the roadway. The right front fender of the Zoox '
        'vehicle was dented. The two individuals fled the scene and Zoox is not aware of any reported injuries. '
        'We question whether this interaction meets the reporting requirements nevertheless, we are submitting '
        'this report out of an abundance of caution. This 10-Day update provides complete information for this '
        'incident.'),
    'nhtsa-sgo-ads-30610-5225-v2': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-5225, version '
        '2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle in autonomous mode was stopped in a merge lane from northbound [XXX] onto [XXX] '
        'yielding and waiting for cross traffic. As it began to creep forward, it again came to a stop and it '
        'was struck by the vehicle behind at low speed. There were no injuries and police were not called. '
        'This report was updated to change the mileage section to "Highlander".'),
    'nhtsa-sgo-ads-30792-6114-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30792-6114, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At 1:45pm, a WeRide vehicle (Car 1) was parked at a [XXX] parking meter - between [XXX] and [XXX] when '
        'another vehicle (Car 2) began reversing in front of the vehicle in question. The reversing vehicle (Car '
        '2) ultimately collided with the front left corner of the WeRide vehicle (Car 1), causing minor damage '
        'to the front bumper. The reversing vehicle (Car 2) did not have any damage. Both drivers were able to '
        "confer with one another seconds after the incident took place. The reversing vehicle's driver did not "
        'possess any form of insurance or registration. WeRide vehicle (Car 1) ADS was not engaged.'),
    'nhtsa-sgo-ads-988-3684-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 988-3684, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2022, Kodiak Robotics, Inc. ("Kodiak") filed an Incident Report (the "Report") under '
        'the Standing General Order 2021-01 (the "Order"). PACCAR, Inc. (Paccar) manufactured the '
        'Kodiak-operated motor vehicle involved in the incident summarized in the Incident Report. Because '
        'Paccar is also a Reporting Entity under the Order, Paccar is submitting a duplicate of the redacted '
        'public copy of the Report. Paccar has selected "Unknown" in the "ADS version" field solely to avoid the '
        "second submission of nonpublic Kodiak CBI. Paccar is in possession of Kodiak's response to this field "
        "and incorporates Kodiak's response into this submission by reference. Paccar's submission is based on "
        'facts supplied to Paccar by Kodiak. Paccar has not investigated the alleged incident and has no '
        'independent knowledge of the facts in the Report.'),
    'nhtsa-sgo-ads-30270-10800-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10800, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On Tuesday, April [XXX], 2025 at 2:37 AM CDT, a Waymo Autonomous Vehicle ("Waymo AV") operating in '
        'Austin, Texas was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was parked at'
        ' the curb facing south on [XXX] when a passenger car reversed into the vacant parallel parking space in '
        'front of the Waymo AV. The rear of the passenger car made contact with the front of the Waymo AV. At the'
        " time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained "
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10717-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10717, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 9:44 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'northeastbound on [XXX] in the rightmost dedicated left turn lane and made an unprotected left turn onto'
        ' [XXX]. As the Waymo AV completed the left turn onto [XXX], a passenger car turning left in the leftmost'
        ' dedicated left turn lane directly next to the Waymo AV crossed into the lane of the Waymo AV and the '
        'front passenger side of the passenger car made contact with the driver side of the Waymo AV. At the time'
        " of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
        'damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10718-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10718, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 8:57 PM CDT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, Texas '
        'was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling eastbound in '
        'the right turn lane of [XXX] and came to a stop in a queue of traffic for a red traffic light at the '
        'intersection with [XXX]. A passenger car travelling directly behind the Waymo AV initially came to a '
        'stop in the queue of traffic, then began to proceed forward and the front of the passenger car made '
        "contact with the rear of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
        'was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'csvr-waymo-20241104-s345': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "345, column 'Accident Detail Description'), transcribed",
        'On November 4, 2024 at 6:28 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in Culver City, '
        'California was in a collision involving an SUV on Culver Boulevard near Sepulveda Boulevard. The Waymo '
        'AV was stopped in traffic for a red light on southwestbound Culver Boulevard with an SUV stopped '
        'directly behind the Waymo AV. Moments later, a passenger car traveling at a high rate of speed '
        'approached the stopped SUV from behind and made contact with the rear of the SUV. The front of the SUV '
        'then made contact with the rear of the stopped Waymo AV. At the time of the impact, the Waymo AV’s Level'
        ' 4 ADS was engaged in autonomous mode. All three vehicles sustained damage.'),
    'csvr-waymo-20240131-s297': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial "
        "297, column 'Accident Detail Description'), transcribed",
        'On January 31, 2024 at 5:15 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger vehicle on Potrero Avenue near 22nd Street. The '
        'Waymo AV was traveling southbound on Potrero Avenue in the leftmost thru lane, adjacent to a dedicated '
        'left turn lane on its left. As the Waymo AV approached the intersection with 22nd Street, it came to a '
        'stop behind its lead vehicle. The passenger vehicle behind the Waymo AV then attempted to change lanes '
        'into the dedicated left turn lane, and made contact with the rear driver side corner of the Waymo AV. At'
        ' the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode. Both vehicles '
        'sustained damage.'),
    'dmvca-waymo-20230820-r519': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 519, column '
        '"Accident Detail Description")',
        'On August 20, 2023 at 5:49 PM PT the mirror of a Waymo Autonomous Vehicle (“Waymo AV”) operating in San '
        'Francisco, CA was struck by a cyclist on Martin Luther King Jr. Drive at Crossover Drive. The Waymo AV '
        'was stopped in traffic on eastbound Martin Luther King Jr. Drive at the intersection with Crossover '
        'Drive, when a cyclist that had been traveling behind the Waymo AV passed the Waymo AV on the left. As '
        'the cyclist passed the Waymo AV, the cyclist made contact with the driver side mirror of the Waymo AV. '
        'At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver '
        'was present (in the driver’s seating position). The Waymo AV sustained damage and the cyclist did not '
        'stop, leaving the scene without exchanging information.'),
    'nhtsa-sgo-ads-30270-10758-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10758, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:31 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was stopped in the '
        'rightmost lane facing southeast on [XXX] in a queue of traffic for a red light at the intersection at '
        '[XXX]. An SUV traveling southeast on [XXX] directly behind the Waymo AV passed the Waymo AV on the left '
        'and the passenger side of the SUV made contact with the rear driver side of the Waymo AV. At the time of'
        " the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV sustained damage. Waymo "
        'is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'dmvca-waymo-20220411-r318': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 318, column '
        '"Accident Detail Description")',
        'On April 11, 2022 at 10:36 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a SUV on Townsend Street and Embarcadero. While traveling '
        'southwest on Townsend Street in manual mode, the Waymo AV test driver approached a double-parked vehicle'
        ' blocking traffic. The Waymo AV test driver pulled behind the double-parked vehicle. At this time, a SUV'
        ' following closely behind the Waymo AV passed the Waymo AV on the left side, making contact with the '
        'rear left sensor of the Waymo AV. The SUV left the scene. At the time of the impact, the Waymo AV’s '
        'Level 4 ADS was not engaged and a test driver was operating the Waymo AV in manual mode. The Waymo AV '
        'sustained minor damage.'),
    'nhtsa-sgo-ads-30270-10570-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10570, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:48 AM MST a Waymo Autonomous Vehicle ("Waymo AV") operating in Scottsdale, '
        'Arizona was in a collision involving an SUV in an alley behind [XXX]. The Waymo AV was traveling '
        'northbound in the alley behind [XXX] when an SUV parked in a carport to the right of the Waymo AV began '
        'to exit its parking stall and proceed into the alley. As the Waymo AV passed the wall of the carport '
        'stall, the front driver side of the SUV made contact with the front passenger side of the Waymo AV. At '
        "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 '
        'because a vehicle involved was towed away. Waymo may supplement or correct its reporting with additional'
        ' information as it may become available.'),
    'dmvca-cruise-20220129-r278': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 278, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("Cruise AV"), operating in supervised autonomous mode, was traveling '
        'southbound on Potrero Avenue between 15th Street and 16th Street. The Cruise AV approached the '
        'intersection with 16th Street as a Toyota Tundra traveling southbound on Potrero Avenue was making a '
        'right turn onto westbound 16th street. The Toyota Tundra was yielding for pedestrians and blocking the '
        'bike lane on southbound Potrero Avenue with Cyclist 1 and Cyclist 2 approaching. The Cruise AV braked '
        'for the two cyclists as Cyclist 3 traveling behind the Cruise AV veered left to avoid another vehicle '
        'pulling out of a curbside parking spot. Cyclist 3 then made contact with the right rear bumper of the '
        'Cruise AV, falling off their bike. Cyclist 3 reported minor injuries related to the incident and police '
        'were not called.'),
    'dmvca-cruise-20220816-r374': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 374, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("Cruise AV"), operating in supervised autonomous mode, was at a complete '
        'stop in response to a red light on eastbound Martin Luther King Jr. Drive at the intersection with '
        'Crossover Drive. A white Honda SUV approaching from the rear in the lane to the left of the Cruise AV '
        'changed into the Cruise AV’s lane, came to a complete stop behind the Cruise AV, and then proceeded '
        'forward to make contact with the rear driver side bumper of the Cruise AV. The white Honda SUV reversed '
        'backwards several feet, proceeded forward, came to a complete stop, and then proceeded forward to make '
        'contact with the Cruise AV again. This caused damage to the Cruise AV’s rear driver side fascia. The '
        'driver of the other vehicle left the scene without exchanging information. Both Cruise AV operators '
        'reported injuries.'),
    'csvr-cruise-20191017-s39': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 39,"
        " column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was stopped at a red light on '
        'southbound Hyde Street at the intersection with Sutter Street when another vehicle behind the Cruise AV '
        'attempted to change into the right adjacent lane and made contact with the right rear corner of the '
        'Cruise AV, damaging the Cruise AV’s right rear radar and assembly. There were no injuries and police '
        'were not called.'),
    'dmvca-apollobaid-20230906-r524': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 524, column '
        '"Accident Detail Description")',
        'An Apollo autonomous vehicle (“AV”) was traveling westbound on Rivera Street in San Francisco in '
        'autonomous mode and stopped for a double-parked vehicle near 31st Avenue. An Apollo safety operator '
        'disengaged the AV from autonomous mode into conventional mode with use of the steering wheel. Then the '
        'AV side-swiped the double-parked vehicle while in conventional mode. There were no injuries and '
        'emergency services were not needed. Both the AV and the second vehicle sustained minor damage.'),
    'dmvca-cruise-20230617-r484': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 484, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'westbound on 19th Street between Capp Street and Mission Street. The Cruise AV slowed to a stop due to a'
        ' pedestrian on a scooter who entered the lane of traffic in front of the AV and started proceeding in '
        'circles. Shortly thereafter, the pedestrian approached the stopped Cruise AV, placed the scooter on the '
        'ground in front of the Cruise AV’s front passenger side tire, and walked away off the roadway. After the'
        ' pedestrian left, the Cruise AV attempted to proceed forward and made contact with the abandoned '
        'scooter. There were no damages to the Cruise AV and there were no reported injuries.'),
    'nhtsa-sgo-ads-30270-7007-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7007, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2023 at 3:23 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San '
        'Francisco, California was in a collision involving a heavy truck on [XXX] near [XXX]. The Waymo AV was '
        'traveling westbound on [XXX] following behind a heavy truck. The heavy truck came to a stop, began to '
        'back up, proceeded forward, and then stopped again. The Waymo AV came to a stop both times the heavy '
        'truck stopped (moving a short distance at a low speed in between the stops). While the Waymo AV '
        'remained stopped the second time, the heavy truck began to reverse again and made contact with the '
        'front of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous '
        'mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of Standing '
        'General Order 2021-01. Waymo may supplement or correct its reporting with additional information as it '
        'may become available.'),
    'nhtsa-sgo-ads-30610-10018-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-10018'
        ', version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle (Vehicle 1) in autonomy was stopped behind traffic in the left turn lane (lane 2) for'
        ' a red traffic signal on [XXX] approaching[XXX] in Las Vegas. At that time, an SUV (Vehicle 2) was a'
        'ttempting to merge onto [XXX] from a parking lot on the right when it entered the travel path of a p'
        'assenger car (Vehicle 3) traveling north on [XXX] in the left through lane (lane 3). The front end o'
        'f Vehicle 2 struck the front passenger side area of Vehicle 3. Vehicle 3 was redirected to the right'
        ' after being impacted by Vehicle 2, and it rear-ended the stopped Zoox vehicle. The Zoox vehicle ope'
        'rator then disengaged from autonomy. The Zoox vehicle operator pulled over into a nearby parking lot'
        ' and returned to the scene to exchange information. The Zoox vehicle sustained minor damage to the r'
        'ear bumper and exhaust pipe. Vehicle 2 sustained moderate damage to the front end with an airbag dep'
        'loyment and was towed from the scene. Vehicle 3 sustained major damage to the front end and passenge'
        'r-side front area with multiple airbag deployments and was towed from the scene. Police and EMS were'
        ' called to the scene, and the driver of Vehicle 3 was transported by an ambulance. The content of th'
        'is report is unchanged from the initial report and provides complete information to date for this in'
        'cident.'),
    'nhtsa-sgo-ads-30270-10175-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10175, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On March [XXX], 2025 at 5:43 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, '
        'Arizona was in a collision involving an SUV on [XXX]. The Waymo AV was stopped in a queue of westbound '
        'traffic for a red traffic light on [XXX]. An SUV traveling eastbound on W Monroe Street attempted to '
        "make a left turn across the stationary Waymo AV's lane of travel to the entrance of a parking lot on "
        'the right of the Waymo AV. As the SUV attempted the left turn the front passenger side of the SUV made '
        "contact with the front of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 "
        'ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under '
        'Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'dmvca-waymo-20241014-r619': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 619, column '
        '"Accident Detail Description")',
        'On October 14, 2024 at 5:04 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in South San '
        'Francisco, California was in a collision involving a pickup truck (Chevrolet El Camino) on El Camino '
        'Real at Westborough Boulevard. The Waymo AV was traveling northwest on El Camino Real when it came to '
        'a stop behind a queue of traffic in the rightmost dedicated left turn lane at the intersection with '
        'Westborough Boulevard. Simultaneously, a pickup truck was traveling southeast on El Camino Real in the '
        'center of three lanes when a passenger car entered the center southeast lane from a driveway to the '
        'right of the pickup truck. As the passenger car entered the center southeast lane just in front of the '
        'pickup truck, the pickup truck swerved to the left, crossing the curbed median. The front of the '
        'pickup truck then made contact with the rear driver side of the stopped Waymo AV and with the rear '
        'driver side of another pickup truck traveling two lanes to the right of the Waymo AV. At the time of '
        'the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode. All three vehicles sustained '
        'damage.'),
    'nhtsa-sgo-ads-30270-9822-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9822,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 4:53 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Ari'
        'zona was in a collision involving a domestic animal on [XXX]. The Waymo AV was traveling southbound '
        'on [XXX]in the center of three southbound lanes, passing a queue of stopped traffic in the leftmost '
        'lane, when a domestic animal emerged from a gap between vehicles in the leftmost lane and crossed th'
        'e path of the Waymo AV. The front of the Waymo AV came in contact with the animal, which did not sur'
        "vive. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Waymo is"
        ' reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or'
        ' correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10689-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10689, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 2:40 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Santa Monica, '
        'California was in a collision involving a heavy truck on [XXX] near [XXX]. The Waymo AV was parked '
        'in-lane facing northwest on a narrow portion of [XXX], with hazard lights activated, when a heavy '
        'truck traveling southeastbound on [XXX] passed the Waymo AV on the right. As the heavy truck passed by '
        'the stationary Waymo AV, the passenger side of the heavy truck trailer made contact with the rear '
        "passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-9881-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9881, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January[XXX], 2025 at 6:41 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, '
        'Arizona was in a collision involving a pickup truck on [XXX]. The Waymo AV was parked at the curb '
        'facing westbound on the north side of [XXX]when a pickup truck reversed out of a driveway on the south '
        'side of [XXX] into the Waymo AV. The rear of the pickup truck made contact with the rear driver side '
        "of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The pickup truck sustained damage. Waymo is reporting this crash under Request No. 2 '
        'of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-8612-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8612, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2024 at 8:23 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, '
        'Arizona was in a collision involving a dog on [XXX] and [XXX]. The Waymo AV was traveling eastbound on '
        '[XXX] at the intersection of [XXX] when a dog ran from the north side of [XXX] towards the path of the '
        'Waymo AV. The Waymo AV engaged heavy braking but as it slowed, the rear driver side of the Waymo AV '
        'made contact with the dog. The dog then crossed behind the Waymo AV onto the south side of [XXX]. At '
        "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Waymo received "
        'notice of injury to the dog. Waymo is reporting this crash under Request No. 2 of Standing General '
        'Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'dmvca-waymo-20201218-r146': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 146, column '
        '"Accident Detail Description")',
        'A Waymo Autonomous Vehicle (“Waymo AV”) was traveling northbound on Sanchez Street in San Francisco in '
        'autonomous mode when it entered the oncoming lane in order to proceed around a garbage truck and '
        'dumpster. As the Waymo AV maneuvered around the garbage truck and dumpster, the Waymo AV test driver '
        'disengaged autonomous mode and took control of the Waymo AV. As the test driver was attempting to '
        're-enter the northbound lane in manual mode, the Waymo AV’s front driver’s side tire drove over the '
        'curb of a traffic island median and the Waymo AV sustained minor damage to its front bumper. No '
        'injuries were reported.'),
    'nhtsa-sgo-ads-30270-8608-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8608, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2024 at 2:35 PM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Arizona was in'
        ' a collision involving an SUV in a parking lot near [XXX] at [XXX]. The Waymo AV was stopped in a parking lot '
        'for a passenger pickup when a parked SUV began reversing out of a diagonal parking stall. The rear driver side'
        " of the SUV made contact with the front of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS"
        ' was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No'
        '. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional informati'
        'on as it may become available.'),
    'nhtsa-sgo-ads-30270-9736-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9736, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 10:39 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Scottsdale, Arizona w'
        'as in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was stopped at a stop sign facing '
        'east in the rightmost of two lanes on [XXX] at the intersection with [XXX]. While the Waymo AV remained stoppe'
        'd, a passenger car traveling partially in the rightmost lane and partially in the left-adjacent dedicated left'
        ' turn lane approached the Waymo AV from behind. As the passenger car was passing the stopped Waymo AV, the pas'
        'senger side of the passenger car made contact with the rear driver side of the stationary Waymo AV. At the tim'
        'e of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Way'
        'mo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle involved wa'
        's towed away. Waymo may supplement or correct its reporting with additional information as it may become avail'
        'able.'),
    'nhtsa-sgo-ads-30270-9635-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9635,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 8:17 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisc'
        'o, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was trave'
        'ling in the leftmost lane of westbound [XXX] when it slowed to a stop to yield to traffic ahead of i'
        't in the same lane. While the Waymo AV remained stopped, a passenger car traveling directly behind t'
        'he Waymo AV approached the Waymo AV from behind. The front driver side of the passenger car made con'
        'tact with the rear passenger side of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 '
        'ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash un'
        'der Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo'
        ' may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-8617-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8617,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2024 at 6:59 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Ar'
        'izona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling eas'
        'tbound on [XXX] and approached the intersection with [XXX] in the singular dedicated left turn lane '
        'to make an unprotected left turn. The Waymo AV pulled forward into the intersection at a slow rate o'
        'f speed and came to a stop, yielding to high speed traffic in the oncoming lane. The passenger car t'
        'hat was following closely behind the Waymo AV then entered the intersection while the Waymo AV conti'
        'nued to yield and the front of the passenger car made contact with the rear of the Waymo AV. At the '
        "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustain"
        'ed damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waym'
        'o may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30610-8290-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-8290,'
        ' version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle (Vehicle 1) in autonomy was gradually slowing to a stop in the right travel lane (lan'
        'e 5) for a red traffic signal on southbound [XXX] at the intersection with [XXX] in Spring Valley, N'
        'evada. A motorcyclist (Vehicle 2), also southbound on [XXX], was traveling at high speed in the left'
        ' through lane (lane 3), aggressively approaching a slowing SUV (Vehicle 3) in lane 3. The motorcycli'
        'st clipped the right rear corner of Vehicle 3, deflecting the motorcycle to the right, causing the m'
        'otorcyclist to lose control and fall to the pavement. The motorcyclist was sliding on the pavement w'
        "hen the motorcycle made contact with the Zoox vehicle's rear bumper. The Zoox vehicle operator disen"
        'gaged from autonomy and brought the vehicle to a stop. The motorcycle came to rest on its right side'
        " with the motorcyclist's right leg stuck underneath the motorcycle. An adjacent bystander immediatel"
        'y aided the motorcyclist and asked the Zoox vehicle operator to move the Zoox vehicle "slightly forw'
        'ard". After the Zoox operator moved the vehicle forward, the bystander lifted the motorcycle and the'
        ' motorcyclist remained on the ground for a short period of time before standing up and walking aroun'
        'd the scene. The motorcyclist was observed to have injuries. Police and EMS were called to the scene'
        ' and the motorcyclist was later transported by an ambulance. The content of this report is unchanged'
        ' from the initial report and provides complete information to date for this incident.'),
    'nhtsa-sgo-ads-669-8495-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 669-8495, version 1, '
        'column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        "In conjunction with Motional's filing of the subject incident, and according to statement(s) provided in Motio"
        "nal's incident report: A Motional AV was operating in Las Vegas, Nevada, in autonomous mode with a safety driv"
        'er at the wheel and an engineer in the front passenger seat. The AV was eastbound on [XXX], approaching the in'
        'tersection with [XXX], in the furthest left of five lanes (lane one), a dedicated left turn lane. Another vehi'
        'cle, originally traveling in a middle through-traffic lane (lane three), had entered lane two, also a dedicate'
        'd left turn lane, and come to a stop almost perpendicular to the flow of traffic. As the AV approached the oth'
        'er vehicle began moving from lane two into lane one without signaling. The safety driver took control, turning'
        " the steering wheel to the left to create space from the other vehicle, momentarily bringing the AV's left fro"
        'nt wheel onto a median curb before safely returning to the roadway after the AV had passed the other vehicle. '
        'There were no injuries or property damage other than a minor tire scuff. law enforcement was not involved.'),
    'csvr-waymo-20210714-s91': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 91, colum"
        "n 'Accident Detail Description'), transcribed",
        'On July 14, 2021 at 4:47 PM PDT, a Waymo Autonomous Vehicle (“Waymo AV”) was proceeding straight westbound on '
        'Clement Street in San Francisco, when a passenger vehicle struck the Waymo AV from behind two times. The passe'
        'nger vehicle then struck the Waymo AV a third time, on the left side of the Waymo AV, as it passed on the left'
        ', then immediately fled the scene. The San Francisco Police Department is investigating the event as a crimina'
        'l act. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver'
        ' was present (in the driver’s seating position).'),
    'nhtsa-sgo-ads-30270-8383-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8383,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2024 at 8:18 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Ariz'
        'ona was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling wes'
        't on [XXX] in the leftmost through lane when it began to slow as it approached a cue of traffic that'
        ' was stopped for a red light. A passenger car traveling behind the Waymo AV then began to change lan'
        'es into the right adjacent lane. As the passenger car was passing the Waymo AV, the driver side of t'
        'he passenger car made contact with the rear passenger side of the Waymo AV. At the time of the impac'
        "t, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo "
        'is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30610-9963-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-9963, version 1'
        ', column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle (Vehicle 1) in autonomy was double parked, waiting for the next ride with brake lights and haza'
        'rd lights activated, on southwest-bound [XXX] in San Francisco. At that time, a passenger car (Vehicle 2) whic'
        'h had been parallel parked in the adjacent right curb lane, pulled out of the parking spot and began attemptin'
        "g a multi-point U-turn ahead of the Zoox vehicle. During the maneuver, Vehicle 2's driver's side rear door mad"
        'e contact with the front left fender of the Zoox vehicle. The Zoox vehicle sustained minor damage to the fende'
        'r. The driver of Vehicle 2 pulled over after the collision to inspect both vehicles, then left the scene short'
        'ly after without exchanging information. There were no reported injuries and police were not called.'),
    'dmvca-waymo-20211204-r256': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 256, column "Accident '
        'Detail Description")',
        'On December 4, 2021 at 4:10 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, CA was '
        'in a collision involving an SUV on Winson Drive between 19th and 20th Avenues. While in autonomous mode, the W'
        'aymo AV turned right from southbound 19th Avenue onto westbound Winston Drive. As the Waymo AV proceeded onto '
        'Winston Drive in the far right lane, an SUV also proceeding westbound on Winston Drive made a continuous right'
        ' lane change from the far left lane, through the middle lane, and entered the far right lane in front of the W'
        'aymo AV. The Waymo AV was decelerating when the test driver transitioned to manual mode. The Waymo AV then mad'
        'e contact with the SUV. At the time of the impact, the Waymo AV’s Level 4 ADS was not engaged and a test drive'
        'r (in the driver’s seating position) was operating the Waymo AV in manual mode. The Waymo AV sustained damage '
        'to its front driver side fender and the SUV sustained damage to its front passenger side fender.'),
    'nhtsa-sgo-ads-30270-7639-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7639, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 4:12 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, Califo'
        'rnia was in a collision involving a motorcycle on [XXX] at [XXX]. The Waymo AV was stopped in traffic in '
        'the leftmost lane on eastbound [XXX] approaching the intersection with [XXX]. A motorcyclist then approac'
        'hed from behind the stopped Waymo AV, lane splitting between the Waymo AVs lane and the rightmost lane. A'
        's the motorcyclist passed, the motorcycle made contact with the rear passenger side corner of the Waymo A'
        'V. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sust'
        'ained damage and the motorcyclist left the scene. Waymo is reporting this crash under Request No. 1 of St'
        'anding General Order 2021-01 because a vulnerable road user was involved. Waymo may supplement or correct'
        ' its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30610-4814-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-4814, vers'
        'ion 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle was proceeding northbound on [XXX]. towards [XXX]. when a passenger vehicle in the right a'
        'djacent lane swerved into the Zoox vehicles lane and made contact with the right passenger side door. The'
        ' other vehicle also made contact with the vehicle in front of them after contacting the Zoox vehicle. The'
        're were no injuries reported at that time and police were not called. Zoox is submitting this updated rep'
        'ort to include new information of a claim dated [XXX], 2023, including unspecified "personal injury." Thi'
        's update provides complete information to date for this incident.'),
    'nhtsa-sgo-ads-30413-9109-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30413-9109, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The May Mobility vehicle was at a designated pick up location waiting for a passenger to get on board. Be'
        'cause of an unprotected turn required to get to the stop, the autonomous vehicle operator took over manua'
        'lly. As the vehicle waited parked at the stop, a car in a parking space in front of the stop backed up in'
        'to the May vehicle at 2mph. This impact occurs 25 seconds after last being in autonomous mode.'),
    'nhtsa-sgo-ads-30270-10078-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10078, ver'
        'sion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On February [XXX], 2025 at 2:36 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco,'
        ' California was in a collision involving an SUV on [XXX]. The Waymo AV was traveling southbound on [XXX] '
        'and came to a stop for a stop sign at the intersection at[XXX]. As the Waymo AV began to proceed straight'
        ' through the intersection, an SUV approached the Waymo AV from behind, and the front of the SUV made cont'
        "act with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in a"
        'utonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of Stand'
        'ing General Order 2021-01. Waymo may supplement or correct its reporting with additional information as i'
        't may become available.'),
    'nhtsa-sgo-ads-30270-9905-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9905, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 7:24 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizon'
        'a was in a collision involving a passenger car on [XXX]. The Waymo AV was traveling westbound on [XXX], a'
        'nd pulled over at the curb. As the Waymo AV came to a stop, the passenger car in front of the Waymo AV re'
        'versed and the rear bumper of the passenger car made contact with the front bumper of the stopped Waymo A'
        "V. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles su"
        'stained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waym'
        'o may supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-6150-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-6150, version 1, c'
        'olumn "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2023 at 6:38 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, Arizona w'
        'as in a collision involving a pickup truck on [XXX] at [XXX]. The Waymo AV was stopped at a red light in '
        'the middle lane, facing northbound on [XXX] at [XXX]. When the light turned green, the pickup truck in th'
        'e left turn lane to the left of the Waymo AV did not immediately proceed, and the Waymo AV attempted to m'
        'erge into the left lane and make a left turn onto westbound [XXX] to pick up a rider that had hailed the '
        'Waymo AV while the vehicle was waiting at the red light. As the Waymo AV moved into the left lane, the ad'
        'jacent pickup truck began to proceed forward and made contact with the drivers side of the Waymo AV. At t'
        'he time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained '
        'damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because a veh'
        'icle involved was towed away. Waymo may supplement or correct its reporting with additional information a'
        's it may become available. This report was originally submitted to NHTSA on August 19, 2023 via emailed .'
        'pdf because NHTSAs online portal was offline for maintenance. Waymo submitted this report again via the r'
        'e-opened portal on August 20, 2023.'),
    'csvr-waymo-20211112-s108': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 108,"
        " column 'Accident Detail Description'), transcribed",
        'On November 12, 2021 at 1:23 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, C'
        'A was in a collision involving a passenger vehicle at Divisadero Street at Turk Street. The Waymo AV was '
        'stopped at a red light on Divisadero Street at Turk Street. When the traffic light turned green, the pass'
        'enger vehicle behind the Waymo AV made contact with the rear of the Waymo AV. At the time of the impact, '
        'the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s'
        ' seating position). The Waymo AV sustained minor damage, and the trailing passenger vehicle sustained min'
        'or damage.'),
    'nhtsa-sgo-ads-30270-6337-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-6337, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On August [XXX], 2023 at 3:36 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Mesa, Arizona wa'
        's in a collision involving a pickup truck on [XXX] at [XXX]. The Waymo AV was stationary adjacent to the '
        'curb on the West side of [XXX]. A pickup truck approached the Waymo from behind and slowed to a stop imme'
        'diately behind the Waymo. The pickup truck then moved slowly forward until the front of the pickup truck '
        'was touching the rear of the Waymo AV. The pickup truck then slowly pushed into the rear of the Waymo AV '
        'for a few seconds before reversing, maneuvering around the Waymo AV, and leaving the scene. At the time o'
        "f the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. W"
        'aymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-669-1762-v3': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 669-1762, versio'
        'n 3, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        "HMA was informed of this incident during a discussion with NHTSA's ODI on November [XXX], 2021. According"
        ' to the information provided, a 2021 Kona EV was being operated by a non-production SAE Level 4 ADAS in a'
        'n unknown mode when the Level 4 system experienced a communication error, switched to an auxiliary backup'
        ' system, resulting in the vehicle crashing into a road sign/ pole. The vehicle was undrivable post-crash.'
        ' No injuries were reported. Hyundai notes that the subject vehicle was produced and sold with SAE Level 1'
        ' and below ADAS only. Hyundai also notes that it has not collaborated with Pony.ai since February 2020. 1'
        '1/[XXX]/2021: No new updates available. 12/[XXX]/2021: No new updates available.'),
    'nhtsa-sgo-ads-30610-2151-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-2151, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        "A Zoox vehicle was traveling through a hotel loading zone, when the driver's side door of a stopped passe"
        'nger vehicle in the right adjacent lane opened, and made contact with the front right sensor of the Zoox '
        'vehicle. There were no injuries and the police were not called. Autonomy was engaged in the 30 second per'
        'iod prior to the collision.'),
    'nhtsa-sgo-ads-30270-9177-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9177, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On October [XXX], 2024 at 10:12 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco,'
        ' California was in a collision involving a domestic animal on [XXX] at [XXX]. The Waymo AV was traveling '
        'eastbound on [XXX]. As it approached the intersection with [XXX], it made contact with a small dog that h'
        'ad apparently been previously struck by a preceding vehicle and was laying in the roadway. At the time of'
        " the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Waymo is reporting this crash und"
        'er Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with ad'
        'ditional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9285-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9285, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 10:29 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco'
        ', California was in a collision involving an asphalt roller vehicle on [XXX] near [XXX]. This section of '
        '[XXX], between [XXX] and [XXX] was an active, open construction zone without lane markings where the road'
        'way was being repaved. The Waymo AV had picked up a passenger on this section of road and was continuing '
        'northbound on [XXX] when it came to a stop before the construction personnel that were working within the'
        ' roadway. While the Waymo AV remained stationary, an asphalt roller vehicle passed the Waymo AV multiple '
        'times. On one such pass while the asphalt roller was reversing, the rear driver side of the asphalt rolle'
        'r vehicle made contact with the rear passenger side of the stationary Waymo AV. At the time of the impact'
        ", the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is repo"
        'rting this crash under Request No. 1 of Standing General Order 2021-01 because a vulnerable road user inf'
        'luenced the driving task of a vehicle involved. Waymo may supplement or correct its reporting with additi'
        'onal information as it may become available.'),
    'nhtsa-sgo-ads-30531-2902-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30531-2902, vers'
        'ion 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Other than noting that the vehicle that struck the Waymo AV had encountered tire debris in its lane, the '
        'content of this report is unchanged from the initial report submitted on May [XXX], 2022 [Report ID # 305'
        '31-[XXX]-1] On May [XXX], 2022 at 3:11 PM PST a Waymo Autonomous Vehicle (Waymo AV) Peterbilt Class 8 sem'
        'i-truck and trailer, operating in Ennis, Texas was in a collision involving a Class 8 semi-truck and trai'
        'ler on northbound [XXX] near [XXX]. The Waymo AV was traveling in autonomous mode in the rightmost lane o'
        'n Interstate [XXX] when a Class 8 semi-truck and trailer began to pass it in the adjacent left lane. Befo'
        're the adjacent Class 8 semi-truck and trailer had fully passed the Waymo AV, it executed a right lane ch'
        'ange and its trailer (the right side, rear section) entered the lane in which the Waymo AV was traveling '
        'and made contact with the driver side of the Waymo AV cab. The Waymo AV transitioned to manual mode and t'
        'he test driver took control. The Waymo AV exited the roadway to the right shoulder of the road and came t'
        "o a stop off of the roadway. At the time of the impact, the Waymo AV's ADS was engaged in autonomous mode"
        ", and a test driver was present (in the driver's seating position). The Waymo AV sustained moderate damag"
        'e and the third-party Class 8 semi-truck and trailer did not stop to exchange information. The Waymo AV t'
        'est driver was transported for medical care and the Waymo AV software operator, seated in the passenger s'
        'eat, later sought medical attention. Transdev Alternative Services is reporting this crash under Request '
        'No. 1 of Standing General Order 2021-01 because an individual involved in the crash was transported from '
        'the scene to a hospital for medical treatment and a vehicle involved was towed away. Transdev may supplem'
        'ent or correct its reporting with additional information as it may become available. This report is ident'
        'ical to WaymoLLC-202205[XXX]-0 (rev.202205[XXX]603622)'),
    'nhtsa-sgo-ads-30270-5611-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-5611, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2023 at 5:54 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, Arizona made'
        ' contact with an asphalt speed bump in a parking lot at [XXX]. The Waymo AV entered the parking lot and t'
        'he Waymo AVs undercarriage then made contact with a speed bump (the AV did not contact any vehicle or oth'
        'er road user). At the time of the contact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The '
        'Waymo AV sustained undercarriage damage. Waymo is reporting this crash under Request No. 1 of the Second '
        'Amended Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or'
        ' correct its reporting with additional information as it may become available.'),
    'dmvca-apple-20221220-r411': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 411, column "Acci'
        'dent Detail Description")',
        'On December 20th, a test vehicle operating in manual driving mode was traveling Northbound on Highway 101'
        ' in Belmont when a nearby Subaru Outback ran over road debris, which was projected onto the test vehicle.'
        ' No injuries were reported and law enforcement was not called to the scene. The test vehicle sustained co'
        'smetic damage to the right headlamp and hood.'),
    'nhtsa-sgo-ads-30530-6125-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30530-6125, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At 09:35 AM CDT on July [XXX], 2023, an Aurora Class 8 truck was traveling southbound in autonomy mode on'
        ' [XXX] near [XXX] when the front windshield was struck by an unknown object. The bottom of the windshield'
        ' had a hole about 3 inches in diameter. The vehicle operator disengaged autonomy and pulled over. The veh'
        'icle was able to be driven from the scene, and there were no reported injuries.'),
    'nhtsa-sgo-ads-30531-10009-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30531-10009, ve'
        'rsion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 4:41 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, C'
        'alifornia was in a collision involving an SUV on [XXX]. The Waymo AV was traveling northeast bound on [X'
        'XX] in the middle of three lanes when a passenger car in the rightmost lane and in front of the Waymo AV'
        ' began to change lanes to the middle lane. The test driver of the Waymo AV transitioned to manual mode, '
        'and began to change lanes into the leftmost lane to avoid the passenger car ahead. During this lane chan'
        'ge manuever, the rear driver side of the Waymo AV made contact with the front passenger side of an SUV t'
        'hat was traveling in the leftmost lane, positioned slightly behind the Waymo AV. At the time of the impa'
        "ct, the Waymo AV's Level 4 ADS was not engaged and a test driver was operating the Waymo AV in manual mo"
        'de. The SUV sustained damage. This is a duplicate of NHTSA report ID [XXX]'),
    'nhtsa-sgo-ads-30270-8844-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8844, ver'
        'sion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On September [XXX], 2024 at 11:27 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco'
        ', California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'south westbound in the right turn lane on [XXX] with its right turn signal activated, and came to a stop'
        ' for a red traffic light at the intersection with [XXX]. As the light turned to a flashing yellow arrow,'
        ' a passenger car approached the Waymo AV from behind, and the front bumper of the passenger car made con'
        'tact with the rear bumper of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was enga'
        'ged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. '
        '2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional infor'
        'mation as it may become available.'),
    'nhtsa-sgo-ads-30792-10691-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30792-10691, ve'
        'rsion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At 2:23pm: WeRide driverless vehicle (vehicle 1) with a safety operator seated in front passenger seat, '
        'was travelling 45mph without much traffic ahead when a BMW x3 (vehicle 2) travelling in the adjacent lef'
        "t lane and in the same direction, merged into vehicle 1's left front quarter panel. Vehicle 1 and Vehicl"
        "e 2 sustained moderate damages. After discussing the incident with vehicle 2's driver, they admitted the"
        'y were attempting to make an upcoming right turn off the expressway. They initiated 2 consecutive right '
        'lane changes abruptly before hitting vehicle 1 on their last attempted lane change. After the initial im'
        'pact, vehicle 1 was forced out of the initial lane, onto a divide, and ultimately came to a stop on the '
        'shoulder of the expressway. At this time both occupants of vehicle 1 and vehicle 2 were able to assess r'
        'espective damages and exchange information. It was determined that there were no injuries. WeRide Vehicl'
        'e (Vehicle 1) required a tow back to the facility.'),
    'dmvca-zoox-20230223-r426': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 426, column "Acc'
        'ident Detail Description")',
        'A Zoox vehicle in manual mode was proceeding southbound in the turn lane on Sixth Street with a green li'
        'ght, yielding to a pedestrian before completing a right turn onto eastbound Harrison Street, in San Fran'
        'cisco, CA with turn signals illuminated. A large truck in the left adjacent lane abruptly turned right a'
        'nd cut in front of the Zoox vehicle making contact with the left front sensor. There were no injuries, t'
        'he other vehicle did not stop to exchange information, and police were not called.'),
    'nhtsa-sgo-ads-30531-9244-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30531-9244, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On Thursday, November [XXX], 2024 at 11:04 CST, a Waymo Autonomous Vehicle ("Waymo AV") operating in Aust'
        'in, Texas was in a collision involving a raised concrete curb in a parking lot on [XXX] near [XXX]. The W'
        'aymo AV was proceeding through a parking lot on [XXX] near [XXX] in autonomous mode when it encountered a'
        ' passenger car parked outside the marked parking spaces occupying a portion of the parking lot apparently'
        ' intended for ingress and egress from the lot rather than parking. The AV came to a stop, and shortly the'
        'reafter the test driver assumed manual control of the AV. The test driver reversed slightly and then proc'
        'eeded through a vacant marked parking space to pass around the parked passenger car, and as the AV crosse'
        'd through the vacant parking space it made contact with a raised concrete curb. At the time of the impact'
        ", the Waymo AV's Level 4 ADS was not engaged and a test driver was operating the Waymo AV in manual. This"
        ' is a duplicate of NHTSA Report ID: 30270-9232-1.'),
    'nhtsa-sgo-ads-30270-9183-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9183, vers'
        'ion 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On October [XXX], 2024 at 8:45 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, Ca'
        'lifornia was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling nor'
        'th on [XXX] behind a passenger car that was traveling in the same direction. The passenger car then began'
        ' to slow and, with its reverse lights illuminated, abruptly began to reverse. The Waymo AV activated its '
        'horn as it came to a complete stop to yield to the passenger car. As the passenger car was reversing at a'
        ' high rate of speed, the Waymo AV briefly reversed before coming to another complete stop. The rear of th'
        'e passenger car then made contact with the front of the stopped Waymo AV. The Waymo AV reversed for a sec'
        'ond time before the passenger car continued reversing and made contact with the front of the Waymo AV aga'
        'in. The passenger car then proceeded straight on [XXX]. At the time of the impact, the Waymo AVs Level 4 '
        'ADS was engaged in autonomous mode. Both vehicles sustained damage and the passenger car left the scene. '
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement'
        ' or correct its reporting with additional information as it may become available.'),
    'dmvca-waymo-20211219-r262': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 262, column '
        '"Accident Detail Description")',
        'On December 19, 2021 at 10:30 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'CA was in a collision involving a passenger vehicle at Fulton Street and 5th Avenue. At the time of the '
        'impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the '
        'driver’s seating position). The Waymo AV was stopped facing southwest on Fulton Street while yielding to '
        'pedestrians in a crosswalk when a passenger vehicle reversed at a low speed from an adjacent driveway into '
        'the right rear bumper of the Waymo AV. Both vehicles sustained minor damage.'),
    'dmvca-cruise-20230321-r442': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 442, column '
        '"Accident Detail Description")',
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling ea'
        'stbound on Clay Street between Hyde Street and Leavenworth Street. Shortly before the intersection w'
        'ith Leavenworth Street, the Cruise AV made contact with a downed power cable on Clay Street and came'
        ' to a stop. This caused damage to the Cruise AV’s front driver side radar assembly. There were no in'
        'juries.'),
    'nhtsa-sgo-ads-30270-5760-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-5760,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On [XXX], 2023 at 09:42 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, Arizona wa'
        's in a collision involving a heavy truck on [XXX], just west of [XXX]. The Waymo AV was traveling we'
        'stbound on [XXX] when it came to a stop, yielding to a U-Haul box truck that was attempting to rever'
        'se into a parking lot to the right of the Waymo AV. The truck exited the lot and re-entered the onco'
        'ming eastbound lane, making contact with the left front end of the Waymo AV. At the time of the impa'
        'ct, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo '
        'is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9214-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9214,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On Saturday, November [XXX], 2024 at 1:35 AM PST, a Waymo Autonomous Vehicle ("Waymo AV") operating '
        'in Daly City, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo A'
        'V was parked facing north on the east side of [XXX] when the front passenger side corner of a black '
        'passenger car traveling north on [XXX] made contact with the rear driver side corner of the Waymo AV'
        '. The impact caused the front of the Waymo AV to make contact with the rear bumper of the passenger '
        'car parked in front of the Waymo AV. The black passenger car then left the scene. At the time of the'
        " impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. All three vehicles sustained dam"
        'age. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because a v'
        'ehicle involved was towed away. Waymo may supplement or correct its reporting with additional inform'
        'ation as it may become available.'),
    'nhtsa-sgo-ads-30270-4484-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-4484,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2022 at 8:48 AM PST a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, A'
        'rizona was in a collision involving a garbage truck on the 500 block of [XXX]. The Waymo AV was trav'
        'eling eastbound on [XXX] when it encountered a stopped garbage truck traveling westbound. The Waymo '
        'AV pulled to the right side of the street and stopped, unable to proceed past the garbage truck and '
        'an SUV parked parallel to the curb. The garbage truck then attempted to pass between the Waymo AV an'
        'd a parked passenger vehicle to the right of the garbage truck, and the garbage truck made contact w'
        'ith the left rear corner of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was e'
        'ngaged in autonomous mode and the Waymo AV was stationary. The Waymo AV sustained damage. Waymo is r'
        'eporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or c'
        'orrect its reporting with additional information as it may become available.'),
}


def quoted_sketch(report_id: str, text: str | None = None) -> Sketch:
    """The extractor's sketch of the quoted narrative `report_id`, or of `text` (a rewording of it) under that id."""
    return extract(text if text is not None else QUOTED[report_id][1], report_id)


def assert_same_reading(report_id: str, reworded: str) -> None:
    """The rewording `reworded` of the quoted narrative `report_id` reads as the narrative does: the same sketch,
    evidence spans aside (`invariance.content`, the comparison the rewording measure makes)."""
    assert content(reworded, report_id) == content(QUOTED[report_id][1], report_id)


def quoted_ego(report_id: str, text: str | None = None) -> tuple[str, str]:
    """The AV's (start, action string) in `quoted_sketch(report_id, text)`."""
    sk = quoted_sketch(report_id, text)
    return sk.ego.start, sk.ego.actions
