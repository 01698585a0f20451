"""Issue 13, the other parties (who counts, position, lane, start, actions), read from real NHTSA SGO narratives the
rules were not written from (tests/text/sgo/study3.jsonl; each entry's `source` beside its text). One test per
reading; each asserts what sketch.md's rules and the study set's gold give.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party
from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_SGO: dict[str, tuple[str, str]] = {
    'nhtsa-sgo-ads-30270-10684-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10684, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 11:14 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Beverly '
        'Hills, California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was '
        'traveling northbound on a narrow portion of [XXX] with vehicles parked at both curbs when it came to'
        ' a stop yielding to a pickup truck traveling southbound on [XXX]. As the pickup truck passed the '
        'stationary Waymo AV, the rear driver side of the pickup truck made contact with the rear driver side'
        " of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
        'mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of Standing '
        'General Order 2021-01. Waymo may supplement or correct its reporting with additional information as '
        'it may become available.'),
    'nhtsa-sgo-ads-30270-10725-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10725, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 2:42 AM CT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, '
        'Texas was in a collision involving a pickup truck in a parking lot off of [XXX] near [XXX]. The '
        'Waymo AV was stopped facing northwest with hazard lights activated in a narrow parking lot off of '
        '[XXX] for a passenger pick-up. A pickup truck traveling southeast in the parking lot began to '
        'maneuver past the Waymo AV on the right. As the pickup truck passed by the stationary Waymo AV, the '
        'passenger side of the pickup truck made contact with the rear passenger side of the Waymo AV. At the'
        " time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Both of the passengers, who were seated in the rear of the Waymo AV, were not '
        'belted at the time of the collision, having just entered the Waymo AV. Waymo is reporting this crash'
        ' under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9654-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9654,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 3:32 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a cyclist on [XXX] at [XXX]. The Waymo AV was '
        'traveling northbound on [XXX] in the rightmost lane, and came to a stop for a red light at the '
        'intersection with [XXX]. While the Waymo AV remained stopped at the intersection, a cyclist '
        'traveling southbound against traffic proceeded through the intersection, passing the Waymo AV on the'
        ' left, and the cyclist made contact with the driver side of the stationary Waymo AV. At the time of '
        "the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained "
        'damage. Waymo is reporting this crash under Request No. 1 of Standing General Order 2021-01 because '
        'a vulnerable road user was involved. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30413-10764-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30413-10764, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A May autonomous shuttle (ego) was stopped at a traffic light in autonomous mode. A vehicle '
        'approaching from behind coasted into the ego vehicle. Our system responded with a software Health '
        'Drop, which immediately took the ego out of autonomous mode (for safety). Minor damage was reported '
        'to our rear sensor and bumper.'),
    'nhtsa-sgo-ads-30270-7935-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7935,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2024 at 10:36 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a van on [XXX] at [XXX]. The Waymo AV was stopped'
        ' for a passenger pickup with the front of the Waymo AV in a parking area and its rear in the travel '
        'lane on [XXX] near the intersection with [XXX]. A van traveling west on [XXX] passed the Waymo AV on'
        ' the left side. The right side of the van came in contact with the rear left side of the Waymo AV. '
        "At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
        'sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General Order '
        '2021-01. Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'csvr-pony.ai-20220517-s159': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 159, column 'Accident Detail Description'), transcribed",
        'On May 17, 2022, a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous '
        'testing vehicle’s rear bumper. At the time of the collision, the Pony.ai vehicle was operating in '
        'autonomous mode with a safety operator in the driver’s seat and was moving at a low speed. The '
        'Pony.ai vehicle did not sustain any damage. There were no injuries or property damage, the police '
        'were not called to the scene, and a Pony.ai employee drove the Pony.ai vehicle back to Pony.ai’s '
        'Irvine facility.'),
    'nhtsa-sgo-ads-30270-9540-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9540,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December[XXX], 2024 at 8:21 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV'
        ' had pulled up to the curb facing northbound on [XXX] for a requested passenger pickup. While '
        'awaiting the passenger, the Waymo AV was partially obstructing access to a residential garage and a '
        'passenger car began reversing out of the garage and the rear driver side of the passenger car made '
        "contact with the rear passenger side of the Waymo AV. At the time of the impact, the Waymo AV's "
        'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this '
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30310-3698-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30310-3698,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Prior to the crash, on August [XXX], 2022 autonomous shuttle (MNCAV2, V005) for the Med City Mover '
        'was travelling southbound on [XXX]. in autonomous ADS mode. The vehicle was functioning normally '
        'prior to the event in autonomous mode. At 16:23 CT, the shuttle entered the intersection of [XXX] '
        'and [XXX]. The shuttle experienced an unknown e-stop. The vehicle behind the shuttle was following '
        'closely and attempting to pass the shuttle at this time and hit the rear left corner of the shuttle.'
        ' No injuries reported to the two passengers on-board the shuttle or the operator or other vehicles '
        'two passengers. Seatbelts were used by the shuttle passengers at the time of the incident. 911 was '
        'called and the Minnesota Department of Public Safety was dispatched to file a report. Details of the'
        ' event can be provided in video format, a police report and an operator summary. The GPX coordinates'
        ' above are approximate at the time of the e-stop. The shuttle had experienced an unknown e-stop at '
        '15:59 CT on [XXX] (no passengers).'),
    'nhtsa-sgo-ads-30270-8061-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8061,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2024 at 8:43 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in [XXX], '
        'California was in a collision involving a passenger car on [XXX]. The Waymo AV was traveling east on'
        ' [XXX]. As the AV approached the all-way stop sign at [XXX], it detected a vehicle traveling west on'
        ' [XXX] and crossing into the opposing lane (the lane in which the AV was traveling). The passenger '
        'car entered the intersection in the opposing lane without slowing. The Waymo AV slowed down and '
        'maneuvered towards the right side of the eastbound lane as the front of the passenger car, still '
        'moving in the wrong direction in the eastbound lane, made contact with the front driver side corner '
        "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
        'mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 of Standing '
        'General Order 2021-01 because a vehicle involved was towed away and because of airbag deployment. '
        'Waymo may supplement or correct its reporting with additional information as it may become '
        'available.'),
    'nhtsa-sgo-ads-30792-6114-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30792-6114,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At 1:45pm, a WeRide vehicle (Car 1) was parked at a [XXX] parking meter - between [XXX] and [XXX] '
        'when another vehicle (Car 2) began reversing in front of the vehicle in question. The reversing '
        'vehicle (Car 2) ultimately collided with the front left corner of the WeRide vehicle (Car 1), '
        'causing minor damage to the front bumper. The reversing vehicle (Car 2) did not have any damage. '
        'Both drivers were able to confer with one another seconds after the incident took place. The '
        "reversing vehicle's driver did not possess any form of insurance or registration. WeRide vehicle "
        '(Car 1) ADS was not engaged.'),
    'nhtsa-sgo-ads-30270-9507-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9507,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 4:07 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a pick-up truck on [XXX] near [XXX]. The Waymo AV'
        ' was traveling southbound in the center lane of [XXX] and slowed down to a stop for a queue of '
        'traffic. A pick-up truck traveling in the right most lane and next to the Waymo AV began to change '
        'lanes into the center lane, and the driver side of the pickup truck made contact with the front '
        'passenger front side of the stationary Waymo AV. After this initial contact, the pick-up truck '
        'maneuvered to the front of the Waymo AV, came to a stop directly in front of the Waymo AV, and after'
        ' a few minutes, the pickup truck reversed, and the rear of the pickup truck made contact with the '
        'front of the stationary Waymo AV. The Waymo AV remained stopped in lane due to the initial contact '
        'the driver of the pickup truck was in and out of their vehicle until leaving the scene. After '
        'approximately 4 minutes, the pick-up truck returned, traveling southbound in the right lane of '
        '[XXX], and the driver side of the pickup truck made contact with the passenger side of the still '
        "stationary Waymo AV. At the time of each point of impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 '
        'of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or'
        ' correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9414-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9414,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 11:07 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV '
        'was parked at the curb in the northwest direction of [XXX]. A pickup truck began to parallel park '
        'behind the Waymo AV, and the front bumper of the pickup truck made contact with the rear bumper of '
        'the Waymo AV. After this initial contact, the pickup truck reversed, then maneuvered away from the '
        'curb towards the lane of travel, and the front passenger side of the pick up truck made contact with'
        " the rear driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. The Waymo AV sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-1420-7995-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 1420-7995, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The subject vehicle (autonomous vehicle - AV) was stopped at a red traffic light, in a queue of '
        'vehicles, heading west on [XXX], with autonomous driving (AD) mode engaged. Once the light turned '
        'green, the queue of vehicles started to move forward, the AV started to move forward with the queue,'
        ' and prior to crossing the intersection, the AV was struck from behind by an SUV. After impact the '
        'safety driver of the AV applied the brakes to disengage AD mode and then proceeded to find a safe '
        'spot to assess the incident by turning right onto [XXX]. The driver of the SUV followed the AV to a '
        'safe location to assess the incident and exchange contact information. There were no reported '
        'injuries, airbag deployments, or tow-aways between either party involved. The AV sustained minor '
        'damage to the rear of the vehicle including the rear bumper cover, rear bumper carrier, and a rear '
        'facing camera. The SUV damage was reported as scratches and dents to the front bumper cover. Both '
        'vehicles were able to safely drive away from the scene. VWGoA does not plan to investigate the '
        "incident any further as the facts and circumstances do not indicate any issue with the vehicle's "
        'performance.'),
    'csvr-waymo-20240319-s304': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 304, column 'Accident Detail Description'), transcribed",
        'On March 19, 2024 at 7:18 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving a passenger car on Division Street at 9th Street. The Waymo '
        'AV was traveling west on Division Street after having stopped at the stop sign at Vermont Street and'
        ' was approaching the intersection with 9th Street when a passenger car approached from behind the '
        'Waymo AV, ran the stop sign at Vermont Street, and made contact with the rear of the Waymo AV. The '
        'front of the passenger car made continuous contact with the rear of the Waymo AV while both vehicles'
        ' were still in motion for a short period of time before the passenger car slowed down and separated '
        'from the AV. The Waymo AV proceeded through the intersection with 9th Street and came to a stop on '
        'Division Street west of the intersection with 9th Street. The passenger car then accelerated and the'
        ' front right corner of the passenger car made contact with the rear left corner of the stationary '
        "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both"
        ' vehicles sustained damage.'),
    'nhtsa-sgo-ads-30610-3719-v2': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30610-3719,'
        ' version 2, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'A Zoox vehicle in autonomy was proceeding at approximately 2mph towards an exit of a private hotel '
        'driveway in Las Vegas, Nevada when it was struck on its right front fender by two individuals '
        'involved in an altercation who had darted out from the side of the roadway. The right front fender '
        'of the Zoox vehicle was dented. The two individuals fled the scene and Zoox is not aware of any '
        'reported injuries. We question whether this interaction meets the reporting requirements '
        'nevertheless, we are submitting this report out of an abundance of caution. This 10-Day update '
        'provides complete information for this incident.'),
    'nhtsa-sgo-ads-30270-9371-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9371,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 2:33 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los '
        'Angeles, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was'
        ' traveling eastbound on [XXX] and came to a stop for a red traffic light in the dedicated left turn '
        'lane, preparing to make a left turn onto northbound [XXX]. A passenger car approached the stationary'
        ' Waymo AV from behind in the adjacent straight lane, and crossed into the lane that the Waymo AV was'
        ' occupying. The front driver side of the passenger car made contact with the rear passenger side of '
        "the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 '
        'of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'dmvca-apple-20240126-r555': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 555, column '
        '"Accident Detail Description")',
        'On January 26th, a test vehicle operating with the automated driving system engaged was traveling '
        'Eastbound on Interstate 580 in Castro Valley when a nearby semi-trailer truck merging from '
        'Interstate 238 generated a draft that projected road debris onto the test vehicle. No injuries were '
        'reported and law enforcement was not called to the scene. The test vehicle sustained minor damage.'),
    'csvr-waymo-20240330-s307': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 307, column 'Accident Detail Description'), transcribed",
        'On March 30, 2024 at 1:33 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco,'
        ' California was in a collision involving an SUV on Jerrold Avenue at Barneveld Avenue. The Waymo AV '
        'was stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the '
        'intersection making a left turn from Barneveld Avenue onto Jerrold Avenue when the front right '
        'corner of the SUV, which was traveling behind the Waymo AV, made contact with the rear left corner '
        "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
        'mode. Both vehicles sustained damage.'),
    'nhtsa-sgo-ads-30270-10561-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10561, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April[XXX], 2025 at 10:41 PM ET a Waymo Autonomous Vehicle ("Waymo AV") operating in Atlanta, '
        'Georgia was in a collision involving a traffic control gate arm on [XXX] near [XXX]. The Waymo AV '
        'was traveling southbound on [XXX] and came to a stop behind a passenger car that had stopped for a '
        'closed traffic control gate arm. While the Waymo AV remained stopped, the gate arm rose to allow the'
        ' passenger car to pass through. After the passenger car had passed through the gate, the Waymo AV '
        'began to proceed through the open gate when the gate arm lowered and made contact with the front of '
        "the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. "
        'The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General'
        ' Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'nhtsa-sgo-ads-30270-8150-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8150,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On June [XXX], 2024 at 11:39 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in [XXX], '
        'California was in a collision involving an SUV near [XXX]. The Waymo AV was stopped curbside for a '
        'pickup facing north on the east side of [XXX] when an SUV that had been stopped partially in-lane '
        'behind the Waymo AV passed the Waymo AV on the left . The passenger side rear door of the SUV made '
        'contact with the rear driver side corner of the Waymo AV. At the time of the impact, the Waymo AVs '
        'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this '
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9552-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9552,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 8:34 PM CT a Waymo Autonomous Vehicle ("Waymo AV") operating in Austin, '
        'Texas was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'southbound in the left hand turn lane on [XXX] and stopped in a queue of traffic at a red light. A '
        'passenger car traveling directly in front of the Waymo AV started to reverse backwards towards the '
        'Waymo AV. The Waymo AV began to reverse to avoid the passenger car, then slowed to a stop. The '
        'passenger car continued to reverse and the rear of the passenger car made contact with the front of '
        "the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. "
        'The Waymo AV sustained damage Waymo is reporting this crash under Request No. 1 of Standing General '
        'Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-5896-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-5896,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2023 at 6:13 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Chandler, '
        'Arizona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'northbound on [XXX] and just passed [XXX] when an oncoming passenger car crossed into the Waymo AVs '
        'lane, toward the Waymo AV. The Waymo AV then stopped as the passenger vehicle continued to approach.'
        ' The passenger vehicle then made contact with the front of the Waymo AV, and then made contact with '
        'the side of the Waymo AV as it left the scene. At the time of the impact, the Waymo AVs Level 4 ADS '
        'was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under '
        'Request No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may'
        ' supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30590-3431-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30590-3431,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'Subject vehicle was on a testing mission in Mountain View, CA. The vehicle was traveling North-bound '
        "on [XXX] operated by the vehicle's Level 4 Automated Driving System and supervised by a safety "
        "driver in the driver's designated seating position, and with a safety operator in the front "
        'passenger seating position. Subject vehicle approached a red light to make a right turn East-bound '
        'onto [XXX]. The safety operator suggested that the safety driver disengage the ADS and make the turn '
        'in manual mode because the vehicle was hesitant in approaching the intersection. The safety driver '
        'disengaged the ADS, and, approximately 250ms later, subject vehicle was lightly struck from behind '
        'by a white Mazda3. Having seen debris on the roadway, the driver and operator believed they had run '
        'over a rock and did not realize they were hit by the vehicle. After concluding the mission, the '
        'driver and operator found damage to a sensor during an inspection. A subsequent review of video led '
        'to discovery of the crash. No injuries were reported, and law enforcement was not called to the '
        "scene. In addition to telematics and video, we also have photographs of the vehicle's damaged "
        'sensor.'),
    'nhtsa-sgo-ads-30270-10776-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10776, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On May [XXX], 2025 at 10:38 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a heavy truck on [XXX] near [XXX]. The Waymo AV '
        'was traveling westbound on [XXX]. The heavy truck traveling eastbound on [XXX] began maneuvering '
        'left into the path of the Waymo AV and the Waymo AV came to a stop. The truck continued and the '
        'front driver side of the heavy truck made contact with the front driver side of the Waymo AV. The '
        'heavy truck then reversed and proceeded eastbound. As the heavy truck passed the stationary Waymo '
        'AV, it made contact with the driver side of the stationary Waymo AV. At the time of the impact, the '
        "Waymo AV's Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. Waymo is "
        'reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle '
        'involved was towed away. Waymo may supplement or correct its reporting with additional information '
        'as it may become available.'),
    'nhtsa-sgo-ads-30270-9330-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9330,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 7:47 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los '
        'Angeles, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was '
        'stationary in the left turn lane of [XXX] preparing for an unprotected left turn onto southwestbound '
        '[XXX] when a passenger car traveling southeast in the center lane of South [XXX] entered the '
        'intersection and departed its lane into the path of left-turning traffic from northwestbound South '
        '[XXX]. The front driver side of the passenger car then made contact with the front driver side of '
        "the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 '
        'of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-6131-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-6131,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2023 at 9:02 AM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was parallel '
        'parked along the right-hand curb on eastbound [XXX] when a passenger car reversed out of a driveway '
        'across the street from the Waymo AV and made contact with the driver side rear bumper of the Waymo '
        'AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. Both '
        'vehicles sustained damage. Waymo is reporting this crash under Request No. 2 of Standing General '
        'Order 2021-01. Waymo may supplement or correct its reporting with additional information as it may '
        'become available.'),
    'nhtsa-sgo-ads-30270-8039-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-8039,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On July [XXX], 2024, at 12:59 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in [XXX], '
        'California was involved in an alleged collision with a non-motorist (cyclist) at a parking garage '
        'exit on [XXX] between [XXX] and [XXX]. The Waymo AV was exiting a parking garage onto [XXX], between '
        '[XXX] and [XXX]. As the Waymo AV approached the garage exit, it stopped for a cyclist who was '
        'approaching from the left. The Waymo AV remained stationary as the cyclist passed in front of the '
        'vehicle, slowed, and appeared to begin to dismount. The cyclist then reached out a hand and made '
        'contact with the front passenger side of the stationary Waymo AV, backed the bicycle up slightly, '
        "dropped the bicycle, then fell to the ground. At the time of the possible impact, the Waymo AV's "
        'Level 4 ADS was engaged in autonomous mode, and a test driver was present. The cyclist received '
        'medical attention at the scene and was reportedly transported to a hospital by local emergency '
        'services. The Waymo AV did not sustain any damage. Even though this event may involve intentional '
        'contact by the bicyclist with a stationary Waymo AV and the occurrence of actual impact between the '
        'Waymo AV and the cycle is not clear, Waymo is reporting this event as a crash under Request No. 1 of '
        'Standing General Order 2021-01 because a media report included an allegation of a crash and because '
        'a vulnerable road user (cyclist) influenced the driving task of a vehicle involved and reportedly '
        'was transported to a hospital for medical treatment as a result of the event. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
}


def _party(report_id: str, k: int = 0) -> Party:
    return extract(_SGO[report_id][1], report_id).npcs[k]


def test_a_party_heading_opposite_the_av_that_passes_it_is_oncoming() -> None:
    # "a pickup truck traveling southbound", the AV northbound: its pass is made from the front, in the oncoming
    # lane (R7, left), not from behind.
    p = _party("nhtsa-sgo-ads-30270-10684-v1")
    assert (p.position, p.lane, p.actions) == ("R7", "left", "a")
    # At a junction the oncoming party is on the opposite approach ("a cyclist traveling southbound against traffic
    # proceeded through the intersection, passing the Waymo AV on the left").
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9654-v1"][1], "nhtsa-sgo-ads-30270-9654-v1")
    assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R2", None)
    assert sk.collision.type == "side_swipe"  # a pass meets the AV along its side


def test_an_oncoming_party_passing_on_the_av_s_right_is_in_its_lane() -> None:
    # "A pickup truck traveling southeast ... began to maneuver past the Waymo AV on the right", the AV facing
    # northwest: the oncoming lane is on the AV's left, so one on its right is in its own lane (R7, same).
    p = _party("nhtsa-sgo-ads-30270-10725-v1")
    assert (p.position, p.lane) == ("R7", "same")


def test_coming_in_contact_and_coasting_into_the_av_are_contacts() -> None:
    # "The right side of the van came in contact with the rear left side of the Waymo AV" ("in", not "into").
    sk = extract(_SGO["nhtsa-sgo-ads-30270-7935-v1"][1], "nhtsa-sgo-ads-30270-7935-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "side_swipe")
    # "A vehicle approaching from behind coasted into the ego vehicle."
    sk = extract(_SGO["nhtsa-sgo-ads-30413-10764-v1"][1], "nhtsa-sgo-ads-30413-10764-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "rear_end")


def test_a_party_out_of_a_driveway_garage_or_parking_space_comes_from_the_curb_side() -> None:
    # "a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous testing vehicle's rear bumper":
    # no side named; parking spots line the curb, on the AV's right.
    p = _party("csvr-pony.ai-20220517-s159")
    assert (p.position, p.lane, p.start, p.actions) == ("R6", "right", "stopped", "k")
    # "a passenger car began reversing out of the garage" (the AV at the curb beside it): on its right too.
    assert _party("nhtsa-sgo-ads-30270-9540-v1").lane == "right"


def test_an_av_named_only_as_an_autonomous_shuttle_is_the_av_not_a_bus() -> None:
    # "autonomous shuttle (MNCAV2, V005) for the Med City Mover was travelling southbound ... The vehicle behind the
    # shuttle ... hit the rear left corner of the shuttle": no operator's name for the AV (its driver, named, is no
    # name of the AV); the vehicle called autonomous is the AV, and the party is the vehicle behind it.
    sk = extract(_SGO["nhtsa-sgo-ads-30310-3698-v1"][1], "nhtsa-sgo-ads-30310-3698-v1")
    assert [(p.category, p.position) for p in sk.npcs] == [("car", "R6")]
    assert sk.collision.with_ == "npc1"


def test_a_participle_joined_by_and_to_a_party_s_participle_is_the_party_s() -> None:
    # "it detected a vehicle traveling west on [XXX] and crossing into the opposing lane": the crossing is the
    # vehicle's (a run, then a move to its left), not the AV's, the clause's subject.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-8061-v1"][1], "nhtsa-sgo-ads-30270-8061-v1")
    assert (sk.npcs[0].position, sk.npcs[0].actions) == ("R2", "af")
    assert "f" not in sk.ego.actions


def test_a_party_backing_into_a_front_corner_of_the_av_came_straight_back_in_its_lane() -> None:
    # "another vehicle (Car 2) began reversing in front of the vehicle in question. The reversing vehicle (Car 2)
    # ultimately collided with the front left corner of the WeRide vehicle": the corner its rear met tells no lane.
    sk = extract(_SGO["nhtsa-sgo-ads-30792-6114-v1"][1], "nhtsa-sgo-ads-30792-6114-v1")
    p = sk.npcs[0]
    assert (p.position, p.lane, p.actions, sk.collision.type) == ("R5", "same", "k", "rear_end")


def test_the_av_described_again_in_parentheses_is_no_party() -> None:
    # "The subject vehicle (autonomous vehicle - AV) was stopped at a red traffic light ... struck from behind by an
    # SUV": the parenthesis says what the AV is; the one other party is the SUV.
    sk = extract(_SGO["nhtsa-sgo-ads-1420-7995-v1"][1], "nhtsa-sgo-ads-1420-7995-v1")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("car", "R6", "same")]


def test_a_pick_up_truck_and_the_pickup_truck_are_one_party() -> None:
    # "A pick-up truck traveling in the right most lane ... the driver side of the pickup truck made contact": one
    # truck, spelled two ways.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9507-v1"][1], "nhtsa-sgo-ads-30270-9507-v1")
    assert len(sk.npcs) == 1


def test_what_follows_after_the_initial_contact_is_after_the_conflict() -> None:
    # "After this initial contact, the pick-up truck maneuvered to the front of the Waymo AV ... reversed, and the
    # rear of the pickup truck made contact with the front": the conflict is the first contact; the string ends there.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9507-v1"][1], "nhtsa-sgo-ads-30270-9507-v1")
    assert (sk.npcs[0].position, sk.npcs[0].lane, sk.npcs[0].actions, sk.collision.type) == \
        ("R5", "right", "af", "side_swipe")
    # "... made contact with the rear bumper of the Waymo AV. After this initial contact, the pickup truck reversed":
    # the reversing is no part of it.
    p = _party("nhtsa-sgo-ads-30270-9414-v1")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "l")


def test_a_second_contact_after_the_party_moved_on_again_is_after_the_conflict() -> None:
    # "... made contact with the rear of the Waymo AV ... before the passenger car slowed down and separated from the
    # AV. ... The passenger car then accelerated and ... made contact with the rear left corner": the conflict is the
    # first contact, the party's string ends there.
    p = _party("csvr-waymo-20240319-s304")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "a")


def test_numbered_individuals_are_people_on_foot() -> None:
    # "it was struck on its right front fender by two individuals involved in an altercation who had darted out from
    # the side of the roadway": people on foot (not a group of traffic), the AV touched by one of them.
    sk = extract(_SGO["nhtsa-sgo-ads-30610-3719-v2"][1], "nhtsa-sgo-ads-30610-3719-v2")
    assert sk.npcs and sk.npcs[0].category == "pedestrian"
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "pedestrian")


def test_a_numbered_group_told_only_in_the_opening_sentence_is_that_many_parties() -> None:
    # The opening sentence tells the contact ("struck ... by two individuals"), so it reads as a summary; but no later
    # sentence names the two one by one ("The two individuals fled the scene"): the count is the opening's (gold:
    # two pedestrians, R5 right, `m` each).
    sk = extract(_SGO["nhtsa-sgo-ads-30610-3719-v2"][1], "nhtsa-sgo-ads-30610-3719-v2")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("pedestrian", "R5", "right")] * 2


def test_a_party_in_the_adjacent_lane_is_on_the_side_of_the_av_it_touched() -> None:
    # "A passenger car approached the stationary Waymo AV from behind in the adjacent straight lane, and crossed into
    # the lane that the Waymo AV was occupying. The front driver side of the passenger car made contact with the rear
    # passenger side": the adjacent lane, its side told by the contact (right), not the AV's own lane.
    p = _party("nhtsa-sgo-ads-30270-9371-v1")
    assert (p.position, p.lane, p.actions) == ("R6", "right", "af")


def test_debris_a_party_threw_at_the_av_came_from_where_that_party_was() -> None:
    # (dev.jsonl, official gold) "a nearby semi-trailer truck merging from Interstate 238 generated a draft that
    # projected road debris onto the test vehicle": the truck merged in from the right; the debris came from there.
    sk = extract(_SGO["dmvca-apple-20240126-r555"][1], "dmvca-apple-20240126-r555")
    assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R5", "right")
    assert (sk.obstacles[0].category, sk.obstacles[0].position, sk.obstacles[0].lane) == ("debris", "R5", "right")


def test_the_av_s_street_is_read_in_its_own_clause_not_a_turning_party_s() -> None:
    # "The Waymo AV was stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the
    # intersection making a left turn from Barneveld Avenue onto Jerrold Avenue": the AV is on Jerrold (the stop sign
    # is where it stopped, not another party's clause), and the turn from Barneveld is the truck's; so the truck
    # turned left onto the AV's street, coming from its right (R3).
    sk = extract(_SGO["csvr-waymo-20240330-s307"][1], "csvr-waymo-20240330-s307")
    assert sorted((p.position, p.actions) for p in sk.npcs) == [("R3", "d"), ("R6", "a")]


def test_a_party_the_av_stopped_behind_is_ahead_in_its_lane() -> None:
    # "The Waymo AV ... came to a stop behind a passenger car that had stopped for a closed traffic control gate arm.
    # ... the gate arm rose to allow the passenger car to pass through": ahead of the AV in its lane (its later
    # mention is no test of the first's words), and passing through the gate is no pass of the AV.
    p = _party("nhtsa-sgo-ads-30270-10561-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R5", "same", "stopped", "i")


def test_stopped_for_a_pickup_facing_north_is_an_errand_not_a_truck() -> None:
    # "The Waymo AV was stopped curbside for a pickup facing north": a passenger pickup; the one party is the SUV.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-8150-v1"][1], "nhtsa-sgo-ads-30270-8150-v1")
    assert len(sk.npcs) == 1


def test_a_party_stopped_behind_the_av_that_passes_it_began_in_its_lane() -> None:
    # "an SUV that had been stopped partially in-lane behind the Waymo AV passed the Waymo AV on the left": it stood
    # in the AV's queue, in its lane, and moved out to the left to pass (R6, same; start, lane change left).
    p = _party("nhtsa-sgo-ads-30270-8150-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R6", "same", "stopped", "if")


def test_a_party_that_backs_up_began_standing() -> None:
    # "A passenger car traveling directly in front of the Waymo AV started to reverse backwards towards the Waymo
    # AV": it backs only from a standstill; "traveling" describes where it was (gold: stopped, k).
    p = _party("nhtsa-sgo-ads-30270-9552-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R5", "same", "stopped", "k")


def test_an_oncoming_party_crossing_into_the_av_s_lane_travelled_first() -> None:
    # "an oncoming passenger car crossed into the Waymo AVs lane, toward the Waymo AV": the possessive written
    # without its apostrophe is the AV's lane; the party came along its own lane, then moved over into the AV's
    # (gold R7, left, "af").
    p = _party("nhtsa-sgo-ads-30270-5896-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R7", "left", "moving", "af")


def test_a_make_and_model_digit_written_as_one_word_is_a_car() -> None:
    # "subject vehicle was lightly struck from behind by a white Mazda3": the party that struck it, behind in its
    # lane (gold: a car, R6 same, `a`).
    sk = extract(_SGO["nhtsa-sgo-ads-30590-3431-v1"][1], "nhtsa-sgo-ads-30590-3431-v1")
    assert [(p.category, p.position, p.lane, p.actions) for p in sk.npcs] == [("car", "R6", "same", "a")]


def test_any_verb_of_motion_with_a_side_into_a_place_is_a_lane_change() -> None:
    # "The heavy truck traveling eastbound ... began maneuvering left into the path of the Waymo AV": oncoming, it
    # moved left into the AV's lane before the contact (gold: R7 left, `af`), as "moved left into", "merging left
    # into" and "veered left into" already read.
    p = _party("nhtsa-sgo-ads-30270-10776-v1")
    assert (p.position, p.lane, p.actions) == ("R7", "left", "af")


def test_a_party_told_leaving_its_lane_changed_lane() -> None:
    # "a passenger car traveling southeast in the center lane ... entered the intersection and departed its lane into
    # the path of left-turning traffic": the opposite approach's car left its lane toward the turning AV (gold: R2,
    # `af`), as "drifted out of its lane" already read.
    p = _party("nhtsa-sgo-ads-30270-9330-v1")
    assert (p.position, p.actions) == ("R2", "af")


def test_a_party_backing_out_from_across_the_street_is_oncoming_and_meets_the_av_broadside() -> None:
    # "The Waymo AV was parallel parked along the right-hand curb ... when a passenger car reversed out of a driveway
    # across the street from the Waymo AV and made contact with the driver side rear bumper": the far side of the
    # AV's road is the oncoming side (R7, left), and a party backing into the AV's side meets it broadside (gold).
    sk = extract(_SGO["nhtsa-sgo-ads-30270-6131-v1"][1], "nhtsa-sgo-ads-30270-6131-v1")
    p = sk.npcs[0]
    assert (p.position, p.lane, p.start, p.actions) == ("R7", "left", "stopped", "k")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "broadside")


def test_a_party_passing_in_front_of_the_av_crosses_its_path_ahead_of_it() -> None:
    # "it stopped for a cyclist who was approaching from the left. The Waymo AV remained stationary as the cyclist
    # passed in front of the vehicle, slowed, and appeared to begin to dismount": a crossing (`m`) ahead of the AV,
    # not a pass from behind along its side (gold: R5 left, `mc`).
    p = _party("nhtsa-sgo-ads-30270-8039-v1")
    assert (p.position, p.lane, p.actions) == ("R5", "left", "mc")
