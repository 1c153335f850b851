<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/2.0" xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:smil20lang="http://www.w3.org/2001/SMIL20/Language" xmlns:pbase="http://www.opengis.net/citygml/profiles/base/2.0" xmlns:smil20="http://www.w3.org/2001/SMIL20/" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:uro="https://www.geospatial.jp/iur/uro/2.0" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:luse="http://www.opengis.net/citygml/landuse/2.0" xmlns:urf="https://www.geospatial.jp/iur/urf/2.0" xmlns:app="http://www.opengis.net/citygml/appearance/2.0" xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns:dem="http://www.opengis.net/citygml/relief/2.0" xmlns:tex="http://www.opengis.net/citygml/texturedsurface/2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:tun="http://www.opengis.net/citygml/tunnel/2.0" xmlns:veg="http://www.opengis.net/citygml/vegetation/2.0" xmlns:sch="http://www.ascc.net/xml/schematron" xmlns:frn="http://www.opengis.net/citygml/cityfurniture/2.0" xmlns:gml="http://www.opengis.net/gml" xmlns:tran="http://www.opengis.net/citygml/transportation/2.0" xmlns:wtr="http://www.opengis.net/citygml/waterbody/2.0" xmlns:brid="http://www.opengis.net/citygml/bridge/2.0" xsi:schemaLocation="https://www.geospatial.jp/iur/uro/2.0 ../../schemas/iur/uro/2.0/urbanObject.xsd https://www.geospatial.jp/iur/urf/2.0 ../../schemas/iur/urf/2.0/urbanFunction.xsd http://www.opengis.net/citygml/2.0 http://schemas.opengis.net/citygml/2.0/cityGMLBase.xsd http://www.opengis.net/citygml/landuse/2.0 http://schemas.opengis.net/citygml/landuse/2.0/landUse.xsd http://www.opengis.net/citygml/building/2.0 http://schemas.opengis.net/citygml/building/2.0/building.xsd http://www.opengis.net/citygml/transportation/2.0 http://schemas.opengis.net/citygml/transportation/2.0/transportation.xsd http://www.opengis.net/citygml/generics/2.0 http://schemas.opengis.net/citygml/generics/2.0/generics.xsd http://www.opengis.net/citygml/waterbody/2.0 http://schemas.opengis.net/citygml/waterbody/2.0/waterBody.xsd http://www.opengis.net/citygml/relief/2.0 http://schemas.opengis.net/citygml/relief/2.0/relief.xsd http://www.opengis.net/citygml/cityobjectgroup/2.0 http://schemas.opengis.net/citygml/cityobjectgroup/2.0/cityObjectGroup.xsd http://www.opengis.net/gml http://schemas.opengis.net/gml/3.1.1/base/gml.xsd http://www.opengis.net/citygml/appearance/2.0 http://schemas.opengis.net/citygml/appearance/2.0/appearance.xsd">
	<gml:boundedBy>
		<gml:Envelope srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3">
			<gml:lowerCorner>35.258297338392 139.73724371347967 2.19367718697</gml:lowerCorner>
			<gml:upperCorner>35.261543955192025 139.74055489539032 21.72735546832999</gml:upperCorner>
		</gml:Envelope>
	</gml:boundedBy>
	<core:cityObjectMember>
		<bldg:Building gml:id="bldg_787d830e-2534-410a-8a2a-a531efeb2533">
			<gml:name>横須賀美術館</gml:name>
			<gen:intAttribute name="図形ID">
				<gen:value>16943</gen:value>
			</gen:intAttribute>
			<gen:intAttribute name="総建物階数">
				<gen:value>1</gen:value>
			</gen:intAttribute>
			<gen:measureAttribute name="１階床面積">
				<gen:value uom="m2">42</gen:value>
			</gen:measureAttribute>
			<gen:doubleAttribute name="床面積換算係数">
				<gen:value>0.9</gen:value>
			</gen:doubleAttribute>
			<bldg:usage codeSpace="../../codelists/Building_usage.xml">422</bldg:usage>
			<bldg:measuredHeight uom="m">6.0</bldg:measuredHeight>
			<bldg:storeysAboveGround>1</bldg:storeysAboveGround>
			<bldg:lod0FootPrint>
				<gml:MultiSurface>
					<gml:surfaceMember>
						<gml:Polygon>
							<gml:exterior>
								<gml:LinearRing>
									<gml:posList>35.25962954418222 139.73892268006682 10.500850847558837 35.259641162301634 139.73890626856112 10.500850847558837 35.25963446013254 139.73889921596987 10.500850847558837 35.259627757963024 139.7388921633798 10.500850847558837 35.259621948904545 139.7389003691329 10.500850847558837 35.259616139845505 139.73890857488482 10.500850847558837 35.259586738382026 139.73887763618922 10.500850847558837 35.25954915708694 139.7389307226852 10.500850847558837 35.25959331855165 139.73897719313715 10.500850847558837 35.25961210921219 139.73895064989156 10.500850847558837 35.259630899866835 139.73892410663376 10.500850847558837 35.25962954418222 139.73892268006682 10.500850847558837</gml:posList>
								</gml:LinearRing>
							</gml:exterior>
						</gml:Polygon>
					</gml:surfaceMember>
				</gml:MultiSurface>
			</bldg:lod0FootPrint>
			<bldg:lod1Solid>
				<gml:Solid>
					<gml:exterior>
						<gml:CompositeSurface>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25962954418222 139.73892268006682 10.500850847558837 35.259630899866835 139.73892410663376 10.500850847558837 35.25961210921219 139.73895064989156 10.500850847558837 35.25959331855165 139.73897719313715 10.500850847558837 35.25954915708694 139.7389307226852 10.500850847558837 35.259586738382026 139.73887763618922 10.500850847558837 35.259616139845505 139.73890857488482 10.500850847558837 35.259621948904545 139.7389003691329 10.500850847558837 35.259627757963024 139.7388921633798 10.500850847558837 35.25963446013254 139.73889921596987 10.500850847558837 35.259641162301634 139.73890626856112 10.500850847558837 35.25962954418222 139.73892268006682 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25962954418222 139.73892268006682 10.500850847558837 35.259641162301634 139.73890626856112 10.500850847558837 35.259641162301634 139.73890626856112 16.491458252427755 35.25962954418222 139.73892268006682 16.491458252427755 35.25962954418222 139.73892268006682 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259641162301634 139.73890626856112 10.500850847558837 35.25963446013254 139.73889921596987 10.500850847558837 35.25963446013254 139.73889921596987 16.491458252427755 35.259641162301634 139.73890626856112 16.491458252427755 35.259641162301634 139.73890626856112 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25963446013254 139.73889921596987 10.500850847558837 35.259627757963024 139.7388921633798 10.500850847558837 35.259627757963024 139.7388921633798 16.491458252427755 35.25963446013254 139.73889921596987 16.491458252427755 35.25963446013254 139.73889921596987 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259627757963024 139.7388921633798 10.500850847558837 35.259621948904545 139.7389003691329 10.500850847558837 35.259621948904545 139.7389003691329 16.491458252427755 35.259627757963024 139.7388921633798 16.491458252427755 35.259627757963024 139.7388921633798 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259621948904545 139.7389003691329 10.500850847558837 35.259616139845505 139.73890857488482 10.500850847558837 35.259616139845505 139.73890857488482 16.491458252427755 35.259621948904545 139.7389003691329 16.491458252427755 35.259621948904545 139.7389003691329 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259616139845505 139.73890857488482 10.500850847558837 35.259586738382026 139.73887763618922 10.500850847558837 35.259586738382026 139.73887763618922 16.491458252427755 35.259616139845505 139.73890857488482 16.491458252427755 35.259616139845505 139.73890857488482 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259586738382026 139.73887763618922 10.500850847558837 35.25954915708694 139.7389307226852 10.500850847558837 35.25954915708694 139.7389307226852 16.491458252427755 35.259586738382026 139.73887763618922 16.491458252427755 35.259586738382026 139.73887763618922 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25954915708694 139.7389307226852 10.500850847558837 35.25959331855165 139.73897719313715 10.500850847558837 35.25959331855165 139.73897719313715 16.491458252427755 35.25954915708694 139.7389307226852 16.491458252427755 35.25954915708694 139.7389307226852 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25959331855165 139.73897719313715 10.500850847558837 35.25961210921219 139.73895064989156 10.500850847558837 35.25961210921219 139.73895064989156 16.491458252427755 35.25959331855165 139.73897719313715 16.491458252427755 35.25959331855165 139.73897719313715 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25961210921219 139.73895064989156 10.500850847558837 35.259630899866835 139.73892410663376 10.500850847558837 35.259630899866835 139.73892410663376 16.491458252427755 35.25961210921219 139.73895064989156 16.491458252427755 35.25961210921219 139.73895064989156 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259630899866835 139.73892410663376 10.500850847558837 35.25962954418222 139.73892268006682 10.500850847558837 35.25962954418222 139.73892268006682 16.491458252427755 35.259630899866835 139.73892410663376 16.491458252427755 35.259630899866835 139.73892410663376 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25962954418222 139.73892268006682 16.491458252427755 35.259641162301634 139.73890626856112 16.491458252427755 35.25963446013254 139.73889921596987 16.491458252427755 35.259627757963024 139.7388921633798 16.491458252427755 35.259621948904545 139.7389003691329 16.491458252427755 35.259616139845505 139.73890857488482 16.491458252427755 35.259586738382026 139.73887763618922 16.491458252427755 35.25954915708694 139.7389307226852 16.491458252427755 35.25959331855165 139.73897719313715 16.491458252427755 35.25961210921219 139.73895064989156 16.491458252427755 35.259630899866835 139.73892410663376 16.491458252427755 35.25962954418222 139.73892268006682 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:CompositeSurface>
					</gml:exterior>
				</gml:Solid>
			</bldg:lod1Solid>
			<bldg:lod2Solid>
				<gml:Solid gml:id="ID_efc23605-ded1-4663-8f64-8c3b8861d797">
					<gml:exterior>
						<gml:CompositeSurface gml:id="ID_de1e541d-be6d-4366-a08b-1662924941b0">
							<gml:surfaceMember xlink:href="#ID_0d8b7b4d-dc7d-401c-8376-ecd255738e38"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_6924c7da-f294-4eef-ab55-3a41bf954269"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_7d6d4336-6415-4fa1-b8a8-961868134629"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_7b0cd7c0-97de-4559-9f87-5e8d0ff410c5"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_f113e78b-63a2-478b-ab09-1a228211f8e6"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_85bbe40c-f488-4de4-8009-da5e55cc0dcb"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_073b22d5-8ef7-49fc-ab22-c39a257cf750"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_284d3fc4-93da-4eea-9fba-1ecfee8e5a2d"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_bc64bf54-871c-4e4b-9e2c-1ac04fc17672"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_562e9d3b-3613-4dc0-9d7e-3a4fd06f23c4"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_0f70f44e-48d2-4b98-90b7-963472d17ca5"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_b4253aec-be52-4783-ac51-6f8ab98d02bf"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_346d5351-c3f9-453b-a8da-252bf2bee408"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_4fac814f-cdca-4b9e-a8a9-4621e8fa5b1c"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_4b20f5e1-8539-45c7-a389-ab3685c9b75e"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_fa131cf0-a44c-496c-8d6d-7b342b709a2d"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_949edecd-1943-4eb0-a64b-1dc2edc749ec"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_99ad1bdb-e1e5-4201-bc87-902ae6e526cb"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_b924fa72-a325-444b-ba52-1b398f5a35d5"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_89783518-fc09-4172-a070-a3aeda4bbb30"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_50f124c9-fcef-4f67-8a0c-7ddfece634b0"></gml:surfaceMember>
							<gml:surfaceMember xlink:href="#ID_e1a7a728-f8c9-4c0a-afd4-5149704a0351"></gml:surfaceMember>
						</gml:CompositeSurface>
					</gml:exterior>
				</gml:Solid>
			</bldg:lod2Solid>
			<bldg:boundedBy>
				<bldg:RoofSurface gml:id="ID_65874e38-c821-4e4b-b484-c2f8e46a414c">
					<bldg:lod2MultiSurface>
						<gml:MultiSurface gml:id="ID_ff193e05-70fc-4a7d-a6cd-61e332626d98">
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_0d8b7b4d-dc7d-401c-8376-ecd255738e38">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_78cdc8c2-d286-4031-b2d6-713683e7a8c0">
											<gml:posList>35.25959331855165 139.73897719313715 16.491458252427755 35.259630899866835 139.73892410663376 16.491458252427755 35.259586738382026 139.73887763618922 16.491458252427755 35.25954915708694 139.7389307226852 16.491458252427755 35.25959331855165 139.73897719313715 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_6924c7da-f294-4eef-ab55-3a41bf954269">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_4a455b73-6d8b-43b0-b295-f3b046f6077e">
											<gml:posList>35.25962954418222 139.73892268006682 12.64095825242779 35.259641162301634 139.73890626856112 12.64095825242779 35.259627757963024 139.7388921633798 12.666458252427791 35.25962954418222 139.73892268006682 12.64095825242779</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_7d6d4336-6415-4fa1-b8a8-961868134629">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_56ab9ae6-33c6-4de3-9a72-ec79053072f6">
											<gml:posList>35.25962954418222 139.73892268006682 12.64095825242779 35.259627757963024 139.7388921633798 12.666458252427791 35.259616139845505 139.73890857488482 12.666458252427791 35.25962954418222 139.73892268006682 12.64095825242779</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:MultiSurface>
					</bldg:lod2MultiSurface>
				</bldg:RoofSurface>
			</bldg:boundedBy>
			<bldg:boundedBy>
				<bldg:GroundSurface gml:id="ID_63bc6613-4c32-4cfc-90a9-3296486a07a9">
					<bldg:lod2MultiSurface>
						<gml:MultiSurface gml:id="ID_df0a7645-af81-4503-af55-14357dcc4d63">
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_7b0cd7c0-97de-4559-9f87-5e8d0ff410c5">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_323fee6d-f591-415f-9c56-cba633cf9652">
											<gml:posList>35.25962954418222 139.73892268006682 10.500850847558837 35.259630899866835 139.73892410663376 10.500850847558837 35.25961210921219 139.73895064989156 10.500850847558837 35.25959331855165 139.73897719313715 10.500850847558837 35.25954915708694 139.7389307226852 10.500850847558837 35.259586738382026 139.73887763618922 10.500850847558837 35.259616139845505 139.73890857488482 10.500850847558837 35.259621948904545 139.7389003691329 10.500850847558837 35.259627757963024 139.7388921633798 10.500850847558837 35.25963446013254 139.73889921596987 10.500850847558837 35.259641162301634 139.73890626856112 10.500850847558837 35.25962954418222 139.73892268006682 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:MultiSurface>
					</bldg:lod2MultiSurface>
				</bldg:GroundSurface>
			</bldg:boundedBy>
			<bldg:boundedBy>
				<bldg:WallSurface gml:id="ID_04160271-b685-4210-b440-f843b7a0f25a">
					<bldg:lod2MultiSurface>
						<gml:MultiSurface gml:id="ID_04b4a628-785a-44a2-8674-5dcace1e195b">
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_f113e78b-63a2-478b-ab09-1a228211f8e6">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_25a24bb3-7b75-4c83-9800-08609c06fdf8">
											<gml:posList>35.25961210921219 139.73895064989156 10.500850847558837 35.259630899866835 139.73892410663376 10.500850847558837 35.259630899866835 139.73892410663376 16.491458252427755 35.25961210921219 139.73895064989156 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_85bbe40c-f488-4de4-8009-da5e55cc0dcb">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_37d2b14d-11e1-4712-83f5-42eed0625f29">
											<gml:posList>35.25959331855165 139.73897719313715 16.491458252427755 35.25959331855165 139.73897719313715 10.500850847558837 35.25961210921219 139.73895064989156 10.500850847558837 35.25959331855165 139.73897719313715 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_073b22d5-8ef7-49fc-ab22-c39a257cf750">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_8ab0651b-5def-4fe5-be36-501d81b29da3">
											<gml:posList>35.25959331855165 139.73897719313715 16.491458252427755 35.25961210921219 139.73895064989156 10.500850847558837 35.259630899866835 139.73892410663376 16.491458252427755 35.25959331855165 139.73897719313715 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_284d3fc4-93da-4eea-9fba-1ecfee8e5a2d">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_5c6b71a6-6847-4df2-998b-c6c4281eff22">
											<gml:posList>35.259616139845505 139.73890857488482 12.666458252427791 35.259586738382026 139.73887763618922 10.500850847558837 35.259586738382026 139.73887763618922 16.491458252427755 35.259616139845505 139.73890857488482 12.666458252427791</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_bc64bf54-871c-4e4b-9e2c-1ac04fc17672">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_de43940b-11de-46de-9223-802ae403f03d">
											<gml:posList>35.259630899866835 139.73892410663376 16.491458252427755 35.259616139845505 139.73890857488482 12.666458252427791 35.259586738382026 139.73887763618922 16.491458252427755 35.259630899866835 139.73892410663376 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_562e9d3b-3613-4dc0-9d7e-3a4fd06f23c4">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_556f4c91-c1f6-4eaf-b2ca-31cf0bb0b0c7">
											<gml:posList>35.259616139845505 139.73890857488482 12.666458252427791 35.259616139845505 139.73890857488482 10.500850847558837 35.259586738382026 139.73887763618922 10.500850847558837 35.259616139845505 139.73890857488482 12.666458252427791</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_0f70f44e-48d2-4b98-90b7-963472d17ca5">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_cea0641e-8890-4d4f-a635-e7945dc9c0fd">
											<gml:posList>35.259630899866835 139.73892410663376 16.491458252427755 35.259630899866835 139.73892410663376 10.500850847558837 35.25962954418222 139.73892268006682 12.64095825242779 35.259630899866835 139.73892410663376 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_b4253aec-be52-4783-ac51-6f8ab98d02bf">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_a7a32a40-2c0e-4453-81c8-6203cc6d8741">
											<gml:posList>35.259630899866835 139.73892410663376 16.491458252427755 35.25962954418222 139.73892268006682 12.64095825242779 35.259616139845505 139.73890857488482 12.666458252427791 35.259630899866835 139.73892410663376 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_346d5351-c3f9-453b-a8da-252bf2bee408">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_271f453e-0cec-4921-aec2-765835daf70c">
											<gml:posList>35.259630899866835 139.73892410663376 10.500850847558837 35.25962954418222 139.73892268006682 10.500850847558837 35.25962954418222 139.73892268006682 12.64095825242779 35.259630899866835 139.73892410663376 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_4fac814f-cdca-4b9e-a8a9-4621e8fa5b1c">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_123e52cc-c626-4590-a4e0-fcafaf957181">
											<gml:posList>35.25954915708694 139.7389307226852 16.491458252427755 35.259586738382026 139.73887763618922 16.491458252427755 35.259586738382026 139.73887763618922 10.500850847558837 35.25954915708694 139.7389307226852 10.500850847558837 35.25954915708694 139.7389307226852 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_4b20f5e1-8539-45c7-a389-ab3685c9b75e">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_eb226d9b-51ca-47cb-b466-11ca6e42d78e">
											<gml:posList>35.25959331855165 139.73897719313715 16.491458252427755 35.25954915708694 139.7389307226852 16.491458252427755 35.25954915708694 139.7389307226852 10.500850847558837 35.25959331855165 139.73897719313715 10.500850847558837 35.25959331855165 139.73897719313715 16.491458252427755</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_fa131cf0-a44c-496c-8d6d-7b342b709a2d">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_548250f2-e511-4660-acaf-ba33a55c1a75">
											<gml:posList>35.25962954418222 139.73892268006682 10.500850847558837 35.259641162301634 139.73890626856112 10.500850847558837 35.259641162301634 139.73890626856112 12.64095825242779 35.25962954418222 139.73892268006682 12.64095825242779 35.25962954418222 139.73892268006682 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_949edecd-1943-4eb0-a64b-1dc2edc749ec">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_5e01148a-7d4b-4134-9749-b7d39040f549">
											<gml:posList>35.25963446013254 139.73889921596987 10.500850847558837 35.259627757963024 139.7388921633798 10.500850847558837 35.259627757963024 139.7388921633798 12.666458252427791 35.25963446013254 139.73889921596987 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_99ad1bdb-e1e5-4201-bc87-902ae6e526cb">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_2e126998-302e-4151-97fd-3d27a592ea77">
											<gml:posList>35.259641162301634 139.73890626856112 12.64095825242779 35.259641162301634 139.73890626856112 10.500850847558837 35.25963446013254 139.73889921596987 10.500850847558837 35.259641162301634 139.73890626856112 12.64095825242779</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_b924fa72-a325-444b-ba52-1b398f5a35d5">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_6cc752ef-4d0e-40db-8707-15e6507e46c2">
											<gml:posList>35.259641162301634 139.73890626856112 12.64095825242779 35.25963446013254 139.73889921596987 10.500850847558837 35.259627757963024 139.7388921633798 12.666458252427791 35.259641162301634 139.73890626856112 12.64095825242779</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_89783518-fc09-4172-a070-a3aeda4bbb30">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_e04eae6d-bca7-4897-9a40-1b65f954a041">
											<gml:posList>35.259616139845505 139.73890857488482 12.666458252427791 35.259621948904545 139.7389003691329 10.500850847558837 35.259616139845505 139.73890857488482 10.500850847558837 35.259616139845505 139.73890857488482 12.666458252427791</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_50f124c9-fcef-4f67-8a0c-7ddfece634b0">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_1cc34692-1a17-4a8a-bcf2-5c11812fde96">
											<gml:posList>35.259621948904545 139.7389003691329 10.500850847558837 35.259627757963024 139.7388921633798 12.666458252427791 35.259627757963024 139.7388921633798 10.500850847558837 35.259621948904545 139.7389003691329 10.500850847558837</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon gml:id="ID_e1a7a728-f8c9-4c0a-afd4-5149704a0351">
									<gml:exterior>
										<gml:LinearRing gml:id="ID_d7148ef9-2213-413f-8376-92f25e4b78ee">
											<gml:posList>35.259616139845505 139.73890857488482 12.666458252427791 35.259627757963024 139.7388921633798 12.666458252427791 35.259621948904545 139.7389003691329 10.500850847558837 35.259616139845505 139.73890857488482 12.666458252427791</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:MultiSurface>
					</bldg:lod2MultiSurface>
				</bldg:WallSurface>
			</bldg:boundedBy>
			<uro:buildingIDAttribute>
				<uro:BuildingIDAttribute>
					<uro:buildingID>14201-bldg-110968</uro:buildingID>
					<uro:branchID>1</uro:branchID>
					<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
					<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
				</uro:BuildingIDAttribute>
			</uro:buildingIDAttribute>
			<uro:buildingDetailAttribute>
				<uro:BuildingDetailAttribute>
					<uro:totalFloorArea uom="m2">42.4879</uro:totalFloorArea>
					<uro:buildingStructureType codeSpace="../../codelists/Building_BuildingStructureType.xml">610</uro:buildingStructureType>
					<uro:buildingStructureOrgType codeSpace="../../codelists/BuildingDetailAttribute_buildingStructureOrgType.xml">2</uro:buildingStructureOrgType>
					<uro:orgUsage2 codeSpace="../../codelists/BuildingDetailAttribute_orgUsage2.xml">134</uro:orgUsage2>
					<uro:surveyYear>2016</uro:surveyYear>
				</uro:BuildingDetailAttribute>
			</uro:buildingDetailAttribute>
			<uro:buildingDisasterRiskAttribute>
				<uro:BuildingLandSlideRiskAttribute>
					<uro:description codeSpace="../../codelists/BuildingLandSlideRiskAttribute_description.xml">1</uro:description>
					<uro:areaType codeSpace="../../codelists/BuildingLandSlideRiskAttribute_areaType.xml">1</uro:areaType>
				</uro:BuildingLandSlideRiskAttribute>
			</uro:buildingDisasterRiskAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">104</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key104.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">105</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key105.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">106</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key106.xml">2</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">107</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key107.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:buildingDataQualityAttribute>
				<uro:BuildingDataQualityAttribute>
					<uro:lod1HeightType codeSpace="../../codelists/BuildingDataQualityAttribute_lod1HeightType.xml">6</uro:lod1HeightType>
				</uro:BuildingDataQualityAttribute>
			</uro:buildingDataQualityAttribute>
		</bldg:Building>
	</core:cityObjectMember>
	<core:cityObjectMember>
		<bldg:Building gml:id="bldg_16418b2d-dc75-4731-ae04-90bbef1d66fe">
			<bldg:consistsOfBuildingPart>
				<bldg:BuildingPart gml:id="bldg_0e947699-9ee6-412f-98d2-6dafb177a681">
					<gml:name>横須賀美術館</gml:name>
					<gen:intAttribute name="図形ID">
						<gen:value>17462</gen:value>
					</gen:intAttribute>
					<gen:intAttribute name="総建物階数">
						<gen:value>2</gen:value>
					</gen:intAttribute>
					<gen:measureAttribute name="１階床面積">
						<gen:value uom="m2">1874</gen:value>
					</gen:measureAttribute>
					<gen:doubleAttribute name="床面積換算係数">
						<gen:value>0.82</gen:value>
					</gen:doubleAttribute>
					<bldg:usage codeSpace="../../codelists/Building_usage.xml">422</bldg:usage>
					<bldg:measuredHeight uom="m">11.3</bldg:measuredHeight>
					<bldg:storeysAboveGround>2</bldg:storeysAboveGround>
					<bldg:lod0FootPrint>
						<gml:MultiSurface>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25934551376892 139.73801401031633 10.385279799663763 35.25953108754047 139.73820553543945 10.385279799663763 35.259548226008484 139.73822325613352 10.385279799663763 35.25956536447386 139.73824097683504 10.385279799663763 35.25962468177446 139.73830216921843 10.385279799663763 35.25968399904368 139.73836336169092 10.385279799663763 35.25981983918423 139.73816767808688 10.385279799663763 35.25995567900424 139.73797199382997 10.385279799663763 35.25961723077406 139.73762268148525 10.385279799663763 35.25946290811946 139.73784493865537 10.385279799663763 35.259424720521174 139.73780584990573 10.385279799663763 35.25941485847638 139.73782017117338 10.385279799663763 35.259404996429865 139.73783449243757 10.385279799663763 35.2594409612081 139.73787037637467 10.385279799663763 35.259443288515165 139.7378731949204 10.385279799663763 35.25934551376892 139.73801401031633 10.385279799663763</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:MultiSurface>
					</bldg:lod0FootPrint>
					<bldg:lod1Solid>
						<gml:Solid>
							<gml:exterior>
								<gml:CompositeSurface>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25934551376892 139.73801401031633 10.385279799663763 35.259443288515165 139.7378731949204 10.385279799663763 35.2594409612081 139.73787037637467 10.385279799663763 35.259404996429865 139.73783449243757 10.385279799663763 35.25941485847638 139.73782017117338 10.385279799663763 35.259424720521174 139.73780584990573 10.385279799663763 35.25946290811946 139.73784493865537 10.385279799663763 35.25961723077406 139.73762268148525 10.385279799663763 35.25995567900424 139.73797199382997 10.385279799663763 35.25981983918423 139.73816767808688 10.385279799663763 35.25968399904368 139.73836336169092 10.385279799663763 35.25962468177446 139.73830216921843 10.385279799663763 35.25956536447386 139.73824097683504 10.385279799663763 35.259548226008484 139.73822325613352 10.385279799663763 35.25953108754047 139.73820553543945 10.385279799663763 35.25934551376892 139.73801401031633 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25934551376892 139.73801401031633 10.385279799663763 35.25953108754047 139.73820553543945 10.385279799663763 35.25953108754047 139.73820553543945 21.72735546832999 35.25934551376892 139.73801401031633 21.72735546832999 35.25934551376892 139.73801401031633 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25953108754047 139.73820553543945 10.385279799663763 35.259548226008484 139.73822325613352 10.385279799663763 35.259548226008484 139.73822325613352 21.72735546832999 35.25953108754047 139.73820553543945 21.72735546832999 35.25953108754047 139.73820553543945 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259548226008484 139.73822325613352 10.385279799663763 35.25956536447386 139.73824097683504 10.385279799663763 35.25956536447386 139.73824097683504 21.72735546832999 35.259548226008484 139.73822325613352 21.72735546832999 35.259548226008484 139.73822325613352 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25956536447386 139.73824097683504 10.385279799663763 35.25962468177446 139.73830216921843 10.385279799663763 35.25962468177446 139.73830216921843 21.72735546832999 35.25956536447386 139.73824097683504 21.72735546832999 35.25956536447386 139.73824097683504 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25962468177446 139.73830216921843 10.385279799663763 35.25968399904368 139.73836336169092 10.385279799663763 35.25968399904368 139.73836336169092 21.72735546832999 35.25962468177446 139.73830216921843 21.72735546832999 35.25962468177446 139.73830216921843 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25968399904368 139.73836336169092 10.385279799663763 35.25981983918423 139.73816767808688 10.385279799663763 35.25981983918423 139.73816767808688 21.72735546832999 35.25968399904368 139.73836336169092 21.72735546832999 35.25968399904368 139.73836336169092 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25981983918423 139.73816767808688 10.385279799663763 35.25995567900424 139.73797199382997 10.385279799663763 35.25995567900424 139.73797199382997 21.72735546832999 35.25981983918423 139.73816767808688 21.72735546832999 35.25981983918423 139.73816767808688 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25995567900424 139.73797199382997 10.385279799663763 35.25961723077406 139.73762268148525 10.385279799663763 35.25961723077406 139.73762268148525 21.72735546832999 35.25995567900424 139.73797199382997 21.72735546832999 35.25995567900424 139.73797199382997 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25961723077406 139.73762268148525 10.385279799663763 35.25946290811946 139.73784493865537 10.385279799663763 35.25946290811946 139.73784493865537 21.72735546832999 35.25961723077406 139.73762268148525 21.72735546832999 35.25961723077406 139.73762268148525 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25946290811946 139.73784493865537 10.385279799663763 35.259424720521174 139.73780584990573 10.385279799663763 35.259424720521174 139.73780584990573 21.72735546832999 35.25946290811946 139.73784493865537 21.72735546832999 35.25946290811946 139.73784493865537 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259424720521174 139.73780584990573 10.385279799663763 35.25941485847638 139.73782017117338 10.385279799663763 35.25941485847638 139.73782017117338 21.72735546832999 35.259424720521174 139.73780584990573 21.72735546832999 35.259424720521174 139.73780584990573 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25941485847638 139.73782017117338 10.385279799663763 35.259404996429865 139.73783449243757 10.385279799663763 35.259404996429865 139.73783449243757 21.72735546832999 35.25941485847638 139.73782017117338 21.72735546832999 35.25941485847638 139.73782017117338 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259404996429865 139.73783449243757 10.385279799663763 35.2594409612081 139.73787037637467 10.385279799663763 35.2594409612081 139.73787037637467 21.72735546832999 35.259404996429865 139.73783449243757 21.72735546832999 35.259404996429865 139.73783449243757 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.2594409612081 139.73787037637467 10.385279799663763 35.259443288515165 139.7378731949204 10.385279799663763 35.259443288515165 139.7378731949204 21.72735546832999 35.2594409612081 139.73787037637467 21.72735546832999 35.2594409612081 139.73787037637467 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259443288515165 139.7378731949204 10.385279799663763 35.25934551376892 139.73801401031633 10.385279799663763 35.25934551376892 139.73801401031633 21.72735546832999 35.259443288515165 139.7378731949204 21.72735546832999 35.259443288515165 139.7378731949204 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25934551376892 139.73801401031633 21.72735546832999 35.25953108754047 139.73820553543945 21.72735546832999 35.259548226008484 139.73822325613352 21.72735546832999 35.25956536447386 139.73824097683504 21.72735546832999 35.25962468177446 139.73830216921843 21.72735546832999 35.25968399904368 139.73836336169092 21.72735546832999 35.25981983918423 139.73816767808688 21.72735546832999 35.25995567900424 139.73797199382997 21.72735546832999 35.25961723077406 139.73762268148525 21.72735546832999 35.25946290811946 139.73784493865537 21.72735546832999 35.259424720521174 139.73780584990573 21.72735546832999 35.25941485847638 139.73782017117338 21.72735546832999 35.259404996429865 139.73783449243757 21.72735546832999 35.2594409612081 139.73787037637467 21.72735546832999 35.259443288515165 139.7378731949204 21.72735546832999 35.25934551376892 139.73801401031633 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:CompositeSurface>
							</gml:exterior>
						</gml:Solid>
					</bldg:lod1Solid>
					<bldg:lod2Solid>
						<gml:Solid gml:id="ID_7c9489b4-28bf-4a64-96f3-0d35ea218295">
							<gml:exterior>
								<gml:CompositeSurface gml:id="ID_3de03436-beb1-46c1-b9b1-cf6fd994200c">
									<gml:surfaceMember xlink:href="#ID_0b05c252-4543-48a3-9106-85c6668b4ab2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2e29473e-69cf-4f65-acf4-482c3b24f62c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0f303ec2-8bc9-4ead-bd63-385edb4227d7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_15c14648-9bb1-40ea-9a56-5dffdbba3356"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d72df88d-fa8f-4cf8-9570-506eef904f53"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_144debeb-cafb-4d81-886e-525150c6f359"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0931e142-5fe5-4520-a9dd-007376a49d15"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_84ee3178-b00b-4b13-ba54-f8bd76cd92d3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cdb67335-cc7c-4550-ab10-86c6b2b631b8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8911eac0-ed21-4856-8230-e78690f6e719"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_59917486-9d4d-4d1f-be23-145332312c65"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c619a29b-2904-4ac5-85be-8ccac5e18a86"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9642d455-17b4-4beb-aad1-1bde1390b20e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_006980eb-b6ea-4df2-a9dd-e41abe214741"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9a51ca54-9073-4441-85b3-2721db7d237f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_922b03cf-cdf2-4013-aff1-3740c846bc6e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d75cafff-ca60-4e39-8c3c-e826b1c1406a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2f9779fe-5516-485c-bfe4-5be60ab72d2f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2314c9f6-be00-4288-8eed-f86123042a6c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_df34369d-1488-41f8-bbaf-70574aad96a6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1b006317-61d3-4abc-8557-cece8b9fe0a7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_abd9f212-fc9e-479a-8e57-ca60991bc16c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_afc681e2-a201-4088-9c0d-bb97966c1e1b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5f8d6ba3-c8bc-45be-a8cc-9cbfc80daefd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f58a217d-87ea-43b6-a8ed-412e0f88cbf2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3a9b5049-6045-4076-946a-6cca0147415e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a8394ee1-8ac6-4ace-8e0a-ef33ea2ce3ca"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e9ffbb05-daab-4e19-8e13-43d09a222780"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5013c281-93b7-4007-becf-fea3ef4926de"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ce817ec4-7216-45e8-87cf-ced17bde95a5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_520f58f5-8f2a-4725-84b2-73fafb888bb8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c1bb30d5-a528-494e-a112-6906337d37a5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5f81b7d9-baef-4e8d-8fd0-750b9b94040f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_84c2c933-fe45-4cb3-8e8d-1b0f60f1059c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5781aec0-bf19-4a3b-9113-7b9832ad65bd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_80f386e2-504f-4762-b022-94326ca604bd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8b1f9ee6-5456-41bb-b9e4-178395706608"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b94e558d-4fc0-4639-8bda-c04a49b61877"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b00f515f-5bc8-438e-8e80-7b64b2555331"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0ea68d7b-74a9-4357-8431-9b3b2bd01732"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c54b05de-0847-4daa-83fb-82bb661e0159"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_51b96af0-5913-4e81-ae22-c1a360660866"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_00ec4f41-8128-4164-9845-b06fcdcbba68"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ce9eebf3-294d-4aec-af10-29cb6a780a88"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a4e3c73c-658d-4d75-ba91-7c43a24bc572"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_275e2e92-0969-4223-9fff-da72427b9b02"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cee7d502-5750-4f4f-a89f-fbf8ea11e9c4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a62ad579-b83c-405d-bda9-0ed17937fc2f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9c243e31-f174-4253-8383-beef1255e5f4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c5bd6b67-c1ca-4ead-9985-34f28c6d51e3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6796f664-5f23-41a9-9e33-5b0169bdf085"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_70752af7-4f9e-4232-8897-0eb99c4d782d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_eba57495-4d7f-4dd6-ac95-f1d5faa200e8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_149700e1-a9f4-45ad-9382-64a6b5459ec5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_221b48bd-80f2-4de3-a6ab-36dfe1c43191"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c5d10f38-f963-4c40-a854-65d2dbc2fc6a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e76eb4a2-dace-4e88-90ef-0d98ceee4eb5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2737265f-71cd-4bb8-a17b-3967c1d4748e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ae405ac2-a567-4894-ba11-ecb22e2d1a95"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0f94d92c-e0b8-40e7-8f9e-62ecfda19049"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b00018d6-e25e-49d3-91e9-b141d08dbf35"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_707edbc9-196a-4f0e-ac3b-6752661f1cfe"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1326e97a-337c-4a2e-afd1-193ee43951e1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b8fe10c3-359c-4341-9c23-9028e74fd03f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_db9aa8c9-37d6-4dc0-8b7e-f1aad68ec1d9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ee205f0b-c70d-4e52-9afe-046c520b3a4c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7372670d-33bb-4b0f-9445-d924391eb981"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_104d4d1f-269f-4800-9f12-6aa0e0f3919c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a4e50b3c-450a-412d-be8d-074d15a0715c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_90d745a7-fdcc-4a51-b8e6-3f0ed78f3ee1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1a9706cb-cc82-46f8-8782-ba1678d1ae8a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_13b33c66-d0c0-44be-a524-32783b6a9fa7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_af65b63b-3172-49d8-9272-398563315af6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b7702df6-9f41-4eab-b81c-0600343a6c9d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9525ceb9-20fb-4486-b4c9-5b90cd9a3b29"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f2d1fbf9-c53d-4390-a2b0-20465c69b3ca"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_39c065f0-e7d8-46bd-bf64-9be65f6549da"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_97ee9962-8c43-4182-b00b-925e25eacd13"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_556113a6-b451-48f2-ae3b-3159b5e586f4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fbab0154-27ed-49f7-859f-3b12c9d72974"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a2c5b4de-4b31-40a7-b52e-6f863fab5b4d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a860893d-87b3-466a-8703-e1495268ed7a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9ac2f47b-c10e-485e-9213-8f217a427872"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d5107499-9da7-4c8f-bb7a-89077c2b22c3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_53c9433d-c65e-40b9-a7ea-98dad953e78d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ef3a34d2-f255-4a18-aa90-59d15c4f0a5c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_56d42a0f-8242-4edf-a9c8-e8ad7ae91136"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cdbcabcf-0871-4a30-aaa4-a47933f39ba4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4a6a32ae-38cb-451f-8589-ee637c5309cd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d85f1e77-a5af-432a-b09b-e1264e17d410"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2d8ae0be-82a4-4e8c-bf4f-4e017309b649"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b0101c68-426e-4dc8-b8dc-3cb37cb09e31"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f7f36b4c-2397-4130-bbc3-37e2c825423e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ea7af8e4-c86b-45eb-bd70-361d6b2fede4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b4905989-1545-4883-b534-71393c1ee024"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2c0d9e58-6c44-4f2b-bf4e-7524cb5c2277"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_568fed17-f12b-4355-b39a-70f2825d0dd1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8ee4f0d3-19c6-4da0-b710-26376ec5b57f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_73a790f7-1a4c-4fa2-af1d-9545e2dc6b77"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_81f3a852-6683-42cf-8de4-d7c471730da3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_445729b0-6110-4d4b-9348-d5be400c0b14"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_aa8ebbd5-05af-4259-9a6c-946bf48fc57c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e4aad4ca-a98c-4c55-9138-599b8d201455"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8e6e1f61-b308-42eb-943d-da1481436a57"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f4ec2c99-3a20-4396-a665-77b694621a4d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b86139a7-e6e9-425c-84df-5affdcbc1e22"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6cbf95ba-d658-42ad-991a-95e53f713c02"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_14fe6843-eb82-461a-b27f-f8ac9645eb7f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_89529d00-bdcc-4723-9e23-4d212b9abf4e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5d49ce32-c3d6-4c89-92ff-bd8143b924a1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_533a01a2-1f87-4bf5-96b7-b2b228206b15"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f3ef135f-7731-4fe7-a905-3f523f9d75de"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_527d64d2-0a6f-44b6-aad6-686181f0cac4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_21604c99-12e8-4868-96c1-6d717bcc2061"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3ebb2be3-2d5b-4c36-849b-fe055bd3e310"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_83e1f664-f095-45d2-a63c-e8ab844d6880"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2e8ed472-2e72-4d35-a6c9-8128ca5752c1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_892b84ae-3bad-4f27-b175-203b4ea94d7d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c9354a31-fb13-46b4-ac6f-2fd5df506f22"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b583acb8-d31a-4a69-9e5a-72131390bf14"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_92ed24d3-0245-4434-9b8e-4071d3082762"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c0e7e7f3-e5b8-4096-b6d1-71581706fd0c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a2f47c17-a737-42fa-b022-6c0c47b1bcdc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1b1cd7e2-9ecb-4b67-a4ca-5180c139cc60"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_38551354-97b0-4139-ba60-814e7a98c041"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6b0ae0c3-983f-42ce-8984-31755f3cec69"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0373db23-0da4-4f05-8c75-139e5867a533"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9c2377f0-e864-4542-8ae7-00a9c56ff3d5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_973b819d-56e1-4709-abe9-d01e1a2e2f60"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_239bea49-1c20-47c2-9ba6-e72d47fa29d1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ce785b6c-11c6-41bd-8617-091202c34dd1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8b7b05fa-8938-4c15-b49b-449943d3394f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_70614227-6d99-4763-abb5-8431d83a7454"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_49e96854-5a53-435a-98ff-dcec24957176"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c97e1a88-7049-427f-8a67-0dc702f321a3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bfd9aaf8-bb0c-4746-b521-587de287f6ee"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9762dad4-99c7-4e05-9966-00bdb024ebe0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c6319706-806e-4d85-9412-7c89bd3d34c4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_11c8075d-b4bf-49b9-8af3-25ffcdfc667f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_171081e7-39a1-40a8-a1f5-ba28ca8373b3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_81546ebe-2f17-459c-aeee-5ab99fadfc9d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e41fb53e-f5e4-4145-b0e3-96c10b56f417"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_083523c2-2033-4d28-89a9-3da1ada56092"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3873cbfb-a075-4e15-a667-042b7e535132"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c15c7f65-573c-4a2c-b164-f832a76cd21d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_448e5c40-5d1f-4dfc-8894-91b213551844"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9c1ceacf-3246-4f51-95e5-f0f839c79c94"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_451f29c4-1e20-4045-b66b-4e3a2ecc6725"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c9da3e04-f125-459a-a819-f40b74709ad8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3854aaa6-f6b4-4ce9-9bdf-dd258496d90f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0546d3a3-f76d-48e2-a0c0-9282476d35d7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e9979ff4-4e58-4144-8c8a-7eaf01ddc839"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_48eb8cca-b476-4d47-8262-e9cbcca2eed3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5b4f1981-98ca-40a5-85d3-c3cd678bd5d0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ff6a22d3-5256-4ca3-a983-ad44a3345ba3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b8a05c2e-6bb0-4c1f-948b-40bff3636e07"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d3c2b704-8137-47fb-a9e2-b93cc6141614"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0750dc35-6555-4393-b2b0-3b8c0f867944"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e2b644c4-805a-499d-97fd-da56c8006ac3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_22fa3183-27a5-404b-9f5b-eb9d85a2ef06"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3183e795-0cc4-4be9-9407-8b3c29890cb1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_aee1219a-a0f6-42ed-9ab7-d91da85354ac"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d5d30b3d-b655-41ed-b259-d87de49039ed"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_58beebce-6101-4107-b036-ee4a2176080a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6c1b8f8b-c029-4b9b-955d-23d5495fcb7a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d927f905-d812-4d20-bd0d-5084c3b661f3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e8659a48-f0e6-48f6-adea-b8e0c8cc1850"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_34d3fcd8-ea07-4d5e-bc27-8bda13c045cd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5900fdbf-3933-417d-8e15-6bb0e50f2995"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_41a93a3d-bc81-438b-a26f-af6318f2eaa0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_464d0d47-55e0-4ea1-b1ee-069810237061"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e3c3f70b-8c07-4108-b5da-f645aecb8831"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3c33fd31-c1c5-46ee-8cb1-6c95a3ac8f69"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_52c96932-e287-4a12-adaa-50d4121fa47a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f4d1e5e3-ca5f-49b5-9b5b-3ba12f27d7ce"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_91d30cca-4fae-4532-903e-9e6e8d6bc5bd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_90223125-53be-4f23-b86b-b075329bc6d8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_78d1c873-e963-4b04-94b9-984950db3e50"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_400ede14-accd-4fab-9b47-d3e6769d5f39"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e2e87abe-b4f4-411c-97c3-7c85c86d28ef"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_75d1542c-52c0-4302-8bae-47a2a9370ba9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a6f54169-2d9a-438a-987b-665801a673c0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a620c3db-fcc5-4f44-bd5b-ec06d225702b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ec531dac-3b0c-404c-8ed4-6008bb5f59f7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ac45fe4f-783b-4b5d-9d21-53504a59b12a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4056951b-e33b-4909-9cb2-719dc6d5c103"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d06fa25a-c891-4340-8be7-1e26eefb0b34"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e3501f41-c327-4226-8f3c-42f10c3fda07"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6ddab183-a241-4299-bc0b-ffb459d92a67"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e846f43e-1701-425d-a687-fa036abd2ad4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e9b12228-a7ae-48d6-9628-d20b35d788b8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_071e6ad9-1ed1-4be0-9b96-b9bcd063309d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7943dca9-b41a-4735-86be-fe4902e262c2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_682de888-9646-479b-92cc-548de074fca1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3ba97743-0ff2-4e4a-a611-fc23bfe1cdc2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cbb6d27c-1d49-4cc7-8732-1776fd45fe3d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_55263213-32bf-4f43-aeeb-a608c80bca5e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b0cb929a-e226-414c-8bd0-9189277c5281"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_202e9272-8c2d-422c-b08c-5a4030401652"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3e931338-a4ce-4059-80af-30686ac14002"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ad7f3038-b8b3-43fe-80c4-6bad6210787d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3db6a45d-616d-4825-8a5d-186837007e2d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_475b9e50-066b-490b-8bdf-3e97437a2978"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_86f44210-2dee-4b01-b228-cd1868015218"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e7e64e1d-5f98-47e5-9318-922c4a21fe5a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2e36affd-9935-43e4-9275-426e56f914e7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_26237b7f-c51f-4268-abd1-20c13f0f7c3f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bdc2961a-b507-48f7-96f9-1e445f10e744"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8c2ad967-d5c5-414c-a2a1-957eaa3f7ca1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_aceb5564-ec92-4daf-a466-3b6153665ad9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c0f3c1dc-9604-401e-a1fb-c9b6d054b8f8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_843f4803-5374-4718-9967-21a7a532292f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b094c05a-8a1c-4c5b-b8f3-31c2e88fb286"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_34b2f039-c56e-4281-a2cc-4dbd55d9e9ed"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c250d256-d22a-461b-8c36-c66d6e562e9c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e1376a1f-3392-4612-8875-1c2f72e93ff3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c9f113f4-7662-4737-b159-1f0f67c356b9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5e684cec-6be9-479e-b2ae-0f9a364f52fe"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c1d5e79b-71c6-4a93-b1a8-a7225c16eef3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9ba8b490-d939-4a42-965a-6b86eb362058"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_46102466-e7d1-4f68-be2f-6924d2f5fb81"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_30367556-f616-4e35-af32-efc3a4114a67"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5a426efb-edeb-46ab-a482-4aec275e6c38"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ed984960-c2e7-4f66-aa36-c1fc5145b5f7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b32acc10-2ab6-4c41-9969-354944922cd9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_68e25f95-8d68-4dd6-9b72-0d4ec421e7ba"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_746db594-061e-4e8e-9168-5b6fe69dd271"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_28c6dceb-0659-4b48-8e8c-1cf83bfd75f2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7cd0b312-0bff-46ef-a2f8-0d521f6381ec"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2b788517-b565-43ea-add0-bac167f37ef3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_db6a338d-1205-4a9b-bfa6-850865af1b5d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_39e657ca-c93e-445a-8a83-127692f0b937"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8dc4a85e-b642-47ec-b887-cbb252ab0efc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b8de2146-cc1f-4242-a333-7c468b7b8cc9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c0d45276-362d-4111-b84f-0c129fceedcd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a9e5774f-6092-4030-8950-a843064cf725"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_42b78613-a14a-4c1a-9114-12264cbd0e08"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ea4055bd-9269-408a-a8a7-e79666c7e5f6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4aecc92c-e935-458d-9f79-4a86a3321295"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_10eebf4a-b6af-40b7-be96-f2469f59f82e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2de98bdd-38ca-4e29-9939-d312d8610781"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_46df70ac-796d-4877-b824-c99d0aff6d0d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_259a549e-f13e-4d25-807b-c030ceac8589"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c938b678-250d-419d-812b-d9c53980c7f8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_449060fa-89a0-4f16-b260-9f6ada513074"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f9008067-82a7-4ff4-b81f-3ab8f691ea18"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e112c815-f165-4cb7-8d08-8aab199b676e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bb41fe6f-0746-427c-9f71-ffe997d6c72d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_82064556-a380-4720-9b4c-0f411b5e8c30"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fb08a902-752c-4729-b771-1629cddb5c99"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d8a617e5-501b-40b5-992f-bb7e127b8313"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1bd4de66-31e6-43aa-beb8-8775bb57203b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2d2542a4-5ec1-4c84-bca8-7011b0326c32"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_513dcb16-471d-47e0-94b1-32e5dbe66408"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8f629602-c96a-48cb-9f0e-298872750b97"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d96d64ae-f0f4-4d09-b092-27427622b238"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5e48cbc4-d74f-4f43-8f8d-2c65f1ded15d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fa9afec1-15a2-49ee-8393-5bf3103a6756"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a82b0ea2-9d6f-4666-91e6-37c19b67d34d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_59a9a5e8-0a01-4909-9957-e34b5b74d63d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d219a082-31d4-42a0-a9e7-0e00c3903e2a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c4542e81-2bfb-468f-9cc4-2802dcd2c1fc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ae1d7eca-1e19-443d-a58d-442f7f947cab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_373d4d21-c55a-49b7-bc45-5445fcda40d8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3ad8a279-90a4-4c29-a20d-02d90c85c822"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7bbf306d-c689-476d-9d10-dd0e1f8a7e5a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e47dcd49-119b-4424-9c50-17482c677ffa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f2cc9c48-0756-4d8c-bb15-143db142e3e7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f5f2118e-7c9f-4bcc-801d-dbc408fdbe62"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_afd6d007-607c-49a0-bf19-d24680c10028"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_71cf1525-4316-4610-ac03-a9347ed32a54"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_71cf663e-a6fd-4b20-b822-851c20adc7f2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d1101f78-ce30-4311-bea8-b2d0bc680cab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c932e035-bfc5-4f63-91a8-147e30ab3b6c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_61dd4625-6e45-4147-ae46-8077765acf83"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d69631f0-4e71-4ff1-a550-cc3ecb457517"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_168996ad-e28d-4f10-bc58-05f5f356251c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9a8a47ee-e492-462e-b8f2-797cb8c48412"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_29673659-7f5b-49a7-a8bb-f26f46a5b0e2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ded6b680-2039-4166-9aeb-d8848796bca4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_73bbce7d-3bb6-4959-baf4-760916fdbbdc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_65427c19-c7f4-4f5e-8c3a-4e59bc2ddab1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9d5546c4-d8af-4325-91d9-27c3a4b53357"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5ef5ea81-87c1-428e-ac7f-b70b41da2251"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_63acea96-0d8e-4ae3-b8ce-09d879b57f29"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2e33f722-8c3d-4852-952b-24d3200a7c0c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ca7b52e1-3a05-4a35-9425-2af181a6ac1c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4a221a79-90b1-4c04-b1f9-1dc172f5199f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5962f7e7-8be6-40f9-9920-ed410b100705"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d2b650f1-03a7-4a7c-9b67-519005ca30b6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7f152770-377a-47f0-86b4-bc67dea52d3c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cc68d6e5-f840-41f2-9cf2-cbc018558c59"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8e752e9f-9a3f-4a84-b376-4dde8cc9f75b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_348b8e81-baf9-4b71-9cdb-921caf2494cd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0219ef56-7ab1-4443-95fe-c12dde68e9f9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9df0a603-27ae-4d79-9493-425c4528cfd5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bed73f19-96c2-43f2-8a4d-930898fcf9ab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cc3db313-7116-48a7-83fd-d89a193809e8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7636a09d-6896-476d-b9e4-867785ea1c67"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_287cba2e-f017-467d-bfce-b4d6783184df"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8a7ec0c6-61f3-47c6-88ab-14ff26a853f3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_740e4c05-194b-433f-b1a1-51517857df16"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ac2863a8-c1c6-4135-bb43-61a508cb1fba"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_afdf0983-effd-4217-a515-bfd7b634e039"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_de0afc3d-663c-4ba0-b0d3-f7982559706a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0f890eff-baab-4acc-a76b-b8dcb7369742"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_30181e8f-3d0c-4a6d-8747-32021bbb08b1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6248c42e-d736-4b3f-afb7-ae274a4e1e4c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_355b2329-195f-43a1-a08e-d095c00753d8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d62263eb-e25f-4f6b-ae25-6aa4e338dd37"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bf5e79b4-6120-4a85-a664-1020a3491925"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_29cd4f7d-87c5-498a-8a7f-bd2b910e565b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_279653dc-0bb5-46fb-ad4f-fc75accad52a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_51152b00-85d4-4c7e-a812-9b63388af164"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_39450ba8-0ff2-4ff7-a9a0-71b0baca74ba"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_dcc3ade8-0952-4294-8f09-c045972e7250"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_282d055f-ebe1-47e5-8a2b-a905fba1de21"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a20cf19a-e6e5-4c9c-a68b-04aea1071580"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7c61cf30-28ba-498b-9121-151cbc956dec"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1df6536a-725c-445c-8058-e04913fb3084"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_111de86d-6af9-4709-a53c-ac1bf9126ea6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3ac25a20-5823-49ff-bede-5278ba5ad1a3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_703e859c-94cd-49d2-bc10-143f2a11a3ff"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_867ad6fe-c475-4ea6-8494-d6b4542268d0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3b750972-c3aa-4136-b1f5-34f608d70a26"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b3986b6e-09fe-4832-81f3-c1b6350370dc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c29467c1-6d55-414a-8f52-3ecd291e9673"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_74ca698c-989c-4f7b-a8cd-700825e0dce8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bdfb612e-7e18-466f-9108-0423b568674f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7981ed1e-05c6-4b9a-9e83-47de4d80f240"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6d90c528-bb8a-458b-b1ef-df5774d02825"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8c037733-a060-4ee8-932c-25e20649a3f2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2964f994-7372-436b-84eb-08d4bdd657ff"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a75afab8-00b2-4004-92ff-076859a9612a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_123797db-44fd-4fac-aff1-83949d9b09ce"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e08f574a-0c4d-4d45-8ca2-6ff546ca3ca2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_13eec824-4ec8-4768-be0a-7b78ba70f3f1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f55de937-5c0a-417a-919f-e5d4d361467f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a1f10f51-d029-44e4-ba2d-c0fa7993f385"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0ab91067-88ca-4398-9f69-1d4697d32af5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1d66e3d1-f665-4748-98eb-e93cac86663b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ab6b87f8-ef1c-4db5-96c7-6a60ccad5b66"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_57cad793-dd72-486a-8b13-c0eb8449d86a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0cb1a79a-fd64-4c2b-9d84-0c0c56565385"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0d1e32b5-e617-4b29-b8e6-2cceebfce8d7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9173b8a6-591f-4382-aa84-658dbd8865ba"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_37d5d573-2ee6-406e-925d-07d3621751e5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_55ece02d-a026-41e5-b297-841230dcea6e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_24344210-c5ff-444a-b613-5c640cf39ef2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_023ea151-15ba-479f-b7f1-31d5fd814c7b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c318874a-d0e1-4859-b02e-655df2db4bff"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_89e9b7f0-deca-4a1e-aa68-d4243042758b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9d3f07d0-8e86-45d2-8f89-2ba807e95fce"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_33015dc0-27ce-4ce0-baaa-bf7ed57d2b6d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6bdb1693-8fd3-4b31-b82f-b173d45e9f68"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c745480f-2fd4-421a-b468-66719c46eb93"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_79a2560d-2ef1-4edc-98bb-9aa3d6ce7f16"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7c95072b-cf70-4846-b703-8a6cf39bdb83"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_73d2211d-ff5e-47dc-bdc8-d60728060f0d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4a94b719-e220-4513-8ccd-6c7f88c197fa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_15db1b8f-8710-40c8-b6f8-42cf23e6e4e5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_40f4e98a-15f2-4103-b3d0-59b596271a6e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_060e077a-61e9-408d-b9fb-d08f02cd5e8b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d955b05c-73f9-4c37-8e9c-24bb01af3688"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e4c6d5b8-fa7d-4615-a318-cfe0edd65ee7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ea5c3648-6b72-40c0-a434-57ac152441ef"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4afe81aa-7bf9-469d-8c91-99da6e5f7618"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5877f253-383e-4685-ad88-8ada69841698"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d007f401-b329-4203-84c9-cc9650177701"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_259b6588-e2f0-4652-927b-6963f92bd522"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d80c6c35-3a42-429f-94b5-58ec09bef9c2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_84791aae-b4a3-4588-9edb-b2379f122ab3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2e079687-3415-4fd9-b7b1-bec7c7cc2e9c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fa4bde1c-6a79-4adf-886c-fc7560aaf7be"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e2d9f96a-1049-4c86-9c2e-c196c3357f1d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0ba5c2f2-d240-4048-86da-b54439230f69"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_54f0f5ec-4a79-456c-a9b8-6357ad8e8af0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a95f895b-d3fe-4599-a6d6-aa56c8e55271"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3feeab2c-ad32-470e-8803-08c7bda1eb1f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0626b043-3092-4bc6-904e-84a65a05e64b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_537f3bd8-60e6-44f3-a163-b3d89feb31ce"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f44e6eef-14c6-476f-bcda-fac23ca0f5dd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5d9c8b95-bd18-455d-924e-6307286c47d9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ae2e33dd-b74b-4d06-bf32-938a7ed72156"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5814bbdc-3cc2-4b26-a668-7d205daf7bb0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bf35d5e4-b76d-4d26-ad3a-fcd01c0d70e7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cb11bb2d-94f7-47c7-b375-0e568b2d3899"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e88c5ae1-b246-485d-9d6b-64daff17dd67"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ec54f690-f8f3-41c6-9c95-5b70b61f8233"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ad81890a-3639-4041-9b8e-ea8cc03bc98a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8c0bc0bf-f5f0-41f0-8a47-d2697b5dc801"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5cf54d22-e1b3-49ed-9fbe-9301e80a8df0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5c9001dc-c7ed-4edb-b3fc-c4bbd61740aa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0bbafa17-137c-444d-a09e-ac4140861f4d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5a59cb49-8eda-4a2e-9b89-726dcd71986f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0c90b213-abf4-4ed4-a5a5-a4a04d270412"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ab898cb2-ff8a-4da5-8524-a829efb1751b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_57a1b441-3a2c-4502-a928-aa3e523c370e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3beb5bb2-9514-472e-bca2-b5f6191091e5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9e4276d3-8354-47b5-b16e-fc060390e5b6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_692b93f3-0efa-41d4-a945-b42d14e231e7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_106fcf89-9865-43fd-bf13-8766286d4bfa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_437ee112-6d5d-482a-a884-c9005151c3cb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_39545912-1e90-4493-8a92-682485bab14a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_97814ed7-badb-4333-83ed-37f48798dcf5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_de75d1a5-4dc6-477d-ae60-0145844f20b8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b28b9099-ddf4-4917-a579-724789d792e5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f5ceabad-7b49-49e8-8c2a-3d9b45c00b81"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_036e96e5-238c-460a-b6dd-72e817e03ea5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fa82b446-92c8-4c1a-977e-4b79782d163a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ad7b31f9-85f5-4561-9b13-0fdafa3c0601"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2f38a5ce-b814-4178-899e-772a55d56c5c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2b36afcb-b21e-4604-9fe7-7c88fce35042"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ee4e820d-fa74-4797-b676-881ddfced74f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1e9d7ed0-b471-48bd-93ba-94032169ac0f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6af31343-7b80-42a5-a4dc-0e0bceab91c5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7c9d2de1-ea4a-4380-8ce1-c5a1d35c193e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b5f1bba9-1bb1-48ae-9520-6bf75e73d5fd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c1451626-2883-4115-89b9-605b114fc2db"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_97fc8ad3-3797-48c3-88d8-84dd15174331"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_25bf7c49-485a-4b69-ae17-3ddcf8394f39"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_66e241d4-a739-40b9-8638-4149113a7399"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_90863f45-d3c2-45e9-9d66-38f926d2f774"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e4ef454a-576b-419b-b8cf-1f2940d2307a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bc424dd5-5d97-412f-a47f-1d2f748c1a8d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9d21be41-8028-440c-88bb-701c0bdb1b6f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fbacdf60-6a5f-4b5e-bd46-02dbb6223b95"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fd5bc2fd-dfa0-4318-8877-c0d7e7339e28"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4d6be433-4db1-461a-962a-fc9250e50423"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9b30334b-2aa5-46ad-a9db-e0b6dc02be38"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c4546fa3-79fd-4beb-8368-971c2ba6c3bf"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a490b6ab-e5be-4b9d-b23d-becb1e4c5828"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8844132e-646a-4bb2-948c-65a2f0518d6a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_693572ec-8371-4ff1-b5f3-186efb3c2ccb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f0adc3cc-0d5d-4126-9da6-fc2ed03d4baf"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a80acf9e-25ac-4630-86a6-1356a2ff2bf1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cae4d7bc-a7b9-4374-873a-ae97d219f7e4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_33cd4bf5-4a33-47ba-b710-59f661ae4dfa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c78562b7-b31f-4de3-8b5b-c51b492a710c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f5cb1498-7c0e-40cc-aaae-4e190ad35bcb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ecd20597-9834-4da0-b305-8e3d256d8f98"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a6048a91-3cdb-45aa-95ed-542efb972383"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_32d13192-3763-459a-a995-f13c0d7ca497"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ca68f407-de63-4d3c-9a5a-2fa1e24ff686"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a11c8ae8-601f-4a06-9e1b-486b3d1bd22c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e0e45454-f357-426a-8d0c-eaf9d4ff7ab8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e8e18091-09ff-4ecc-84b3-6aa1abdae106"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3f27797f-55da-4140-bdd4-12a16f34bbc9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_311dab8c-3a34-418f-9b5c-00b2c0782197"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1ef118aa-a1c1-42d3-aae1-6037618a9315"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_41b7d46b-b4f9-455e-a66d-780d284c7783"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1d2b2ac3-21d2-409d-83b2-a56d96659fae"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5ef857c9-525d-4da9-9403-fd94f150892c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ba2ff89e-1ec6-4db3-aa3a-9859adeeddc1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f7dbcc26-dfa9-4414-a4f3-4c7decb454ce"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c90039c9-eb26-46ea-a8d1-b37d4eccae70"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9010c58c-1ef4-45d2-9968-1278153e4e63"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8a1079ee-0f22-498e-96df-a4031f5cc413"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ef88dfee-df9f-4dd1-85d1-df651468d2af"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_780ec64a-2f30-4a40-98f9-d88a0569078c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_14fbcadd-a885-4d72-bcba-2eed9a6c375a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_728a94da-a730-42f6-b2b4-1e11388cd20b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4bb7b17d-0943-4f05-82c3-ad3c5838b9dc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4ed60c31-354d-42a3-80d6-035d8e1b435a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_87f3dc9f-d829-45a1-a45f-45cb640501c8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bd2c0fa2-4863-4803-a8ff-433c71f14de4"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_902faf81-3925-41a7-9c11-84eac1ddd22b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d98212b6-a6d2-4562-80cc-960ed8c2fb8e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_e7425049-36b7-4226-b99d-d935de7196c8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5d3c62eb-c94e-4b33-921e-8e82165de11b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_458cb140-1189-4334-8207-e6c5f6923af5"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f711d49e-6123-4231-82eb-058f556538e9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_66c57336-030c-457a-bf88-2776f7b1334a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_773cdf50-7049-4044-a6e3-70b2391abd02"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7c325b35-64de-4fd4-b6bf-e12b44d2f9ec"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9acdf131-6bb4-41cf-96a8-7f1f5e11db9d"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8dd2339c-3c4d-46a9-9105-9fef71982a18"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_16a35caa-b81f-489b-ae63-b3d72b11300a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0220353e-9e1c-4944-897b-85ec1fbdbbeb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0b81bce2-8fd8-48d5-8cfe-982bb4bf08ec"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9a8c3281-2f7f-461e-8750-ee5c39dfcabb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_855588b3-8e52-4a43-93d8-45cd6fb52916"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b7a13e9a-519f-4376-b7fd-6406fe37fc7a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b31569a9-5e8d-46fa-bf22-da710f865320"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_49ac018f-57f8-407f-b4d0-6fb89a81e340"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d59c678c-edaa-465b-85ea-ba08a39f291b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7d5a54b2-dfd5-460d-b2ae-8d072161af69"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5293bac5-caad-4dbf-974d-5f8a873886ab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5a9d687a-f8ae-4989-81b0-16f2d7d3c5e9"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2cfe1a95-b9ae-4e1e-8a4f-bec07ccec2e6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c41cbe7b-c264-456a-b311-a706e1607e74"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_efe37995-2696-49c5-8609-02c8836c5fad"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1f4456e0-b44d-4768-98a5-9adfa0e56b11"></gml:surfaceMember>
								</gml:CompositeSurface>
							</gml:exterior>
						</gml:Solid>
					</bldg:lod2Solid>
					<bldg:boundedBy>
						<bldg:RoofSurface gml:id="ID_03937faa-7db2-4ace-a311-53c002a4ca96">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_e3a80145-7603-4139-a3fa-1987922a9d52">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0b05c252-4543-48a3-9106-85c6668b4ab2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9b5dafba-6db2-4b9b-b3ae-9d077d755c86">
													<gml:posList>35.259666051699966 139.73773626223345 17.918 35.25961723077406 139.73762268148525 17.918 35.25965540144442 139.73773080159927 17.918 35.259666051699966 139.73773626223345 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2e29473e-69cf-4f65-acf4-482c3b24f62c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_59beb55f-a712-4f5c-bdef-a35e8f5ffff6">
													<gml:posList>35.25952795504885 139.73791152067759 17.918 35.25956674088509 139.73782787252776 17.918 35.25946290811946 139.73784493865537 17.918 35.25952795504885 139.73791152067759 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0f303ec2-8bc9-4ead-bd63-385edb4227d7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_974c08e6-70fa-4e02-859b-75d21d5bf7ad">
													<gml:posList>35.25954306425423 139.7379244274751 17.918 35.259607562148425 139.73790188784028 17.918 35.25957140349773 139.73784207742708 17.918 35.25952795504885 139.73791152067759 17.918 35.25954306425423 139.7379244274751 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_15c14648-9bb1-40ea-9a56-5dffdbba3356">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aa2b4a75-a601-43bd-9723-c5764387a0dc">
													<gml:posList>35.25956587536673 139.73794197411962 17.918 35.259607562148425 139.73790188784028 17.918 35.25954306425423 139.7379244274751 17.918 35.25956587536673 139.73794197411962 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d72df88d-fa8f-4cf8-9570-506eef904f53">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_abfb6352-d456-4f70-a766-af2c4cdf6379">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.259607562148425 139.73790188784028 17.918 35.25956587536673 139.73794197411962 17.918 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_144debeb-cafb-4d81-886e-525150c6f359">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b865c566-d425-47b6-883e-2e97b1504819">
													<gml:posList>35.25958757311341 139.7379536862642 17.918 35.25959506323896 139.7379526773771 17.918 35.259580504322734 139.73795172729461 17.918 35.25958757311341 139.7379536862642 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0931e142-5fe5-4520-a9dd-007376a49d15">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aa37274a-f3ad-4ca2-a14d-7f30765c5725">
													<gml:posList>35.25959506323896 139.7379526773771 17.918 35.25960347874844 139.73794774389137 17.918 35.259580504322734 139.73795172729461 17.918 35.25959506323896 139.7379526773771 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_84ee3178-b00b-4b13-ba54-f8bd76cd92d3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6a5b48d4-6a7a-47e0-99d4-2f9415d59f05">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.25960347874844 139.73794774389137 17.918 35.25961357483846 139.73792490533882 17.918 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cdb67335-cc7c-4550-ab10-86c6b2b631b8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_86c24104-9ca6-44c2-b903-186b7c79c6be">
													<gml:posList>35.25960347874844 139.73794774389137 17.918 35.259609584950034 139.73794073595585 17.918 35.25961261674252 139.7379330722079 17.918 35.25960347874844 139.73794774389137 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8911eac0-ed21-4856-8230-e78690f6e719">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_94943e92-3da8-4328-afaf-235db2a69543">
													<gml:posList>35.25960347874844 139.73794774389137 17.918 35.25961261674252 139.7379330722079 17.918 35.25961357483846 139.73792490533882 17.918 35.25960347874844 139.73794774389137 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_59917486-9d4d-4d1f-be23-145332312c65">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_76380a1f-1c9c-4e4f-aa2d-ecd43dcd3513">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.25961357483846 139.73792490533882 17.918 35.25961311779565 139.73791688300133 17.918 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c619a29b-2904-4ac5-85be-8ccac5e18a86">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0caf0c3a-3607-428d-b66f-6fa2a0f963fe">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.25961311779565 139.73791688300133 17.918 35.25961162558559 139.73791074120786 17.918 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9642d455-17b4-4beb-aad1-1bde1390b20e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e6900f95-7391-498d-826d-f942623fef2c">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.25961162558559 139.73791074120786 17.918 35.259607562148425 139.73790188784028 17.918 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_006980eb-b6ea-4df2-a9dd-e41abe214741">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5045cb78-c34b-4ae0-9ef5-2d56c581d2aa">
													<gml:posList>35.259850023986424 139.73797430423687 17.918 35.25995567900424 139.73797199382997 17.918 35.25984999934051 139.73796590770004 17.918 35.259850023986424 139.73797430423687 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9a51ca54-9073-4441-85b3-2721db7d237f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c6ea3cbd-34e9-42c2-805c-507e5fb8fbda">
													<gml:posList>35.25952795504885 139.73791152067759 17.918 35.25957140349773 139.73784207742708 17.918 35.25956863825879 139.7378333983881 17.918 35.25952795504885 139.73791152067759 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_922b03cf-cdf2-4013-aff1-3740c846bc6e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_40b76289-dc0e-43d7-920e-32752d9d1129">
													<gml:posList>35.25952795504885 139.73791152067759 17.918 35.25956863825879 139.7378333983881 17.918 35.25956674088509 139.73782787252776 17.918 35.25952795504885 139.73791152067759 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d75cafff-ca60-4e39-8c3c-e826b1c1406a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_eaa16ad5-d6a4-4257-b28c-3b7d34655d63">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.25956674088509 139.73782787252776 17.918 35.259565011686625 139.73781842295804 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2f9779fe-5516-485c-bfe4-5be60ab72d2f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6da00da4-d264-4cf7-8409-16404249069e">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.259565011686625 139.73781842295804 17.918 35.25956475477397 139.73780128948985 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2314c9f6-be00-4288-8eed-f86123042a6c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ff408e95-6dc9-4274-8085-5a623dce91f2">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.25956475477397 139.73780128948985 17.918 35.259565888566 139.73778731957597 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_df34369d-1488-41f8-bbaf-70574aad96a6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2e9203a8-1bb7-4fe0-94d2-9954ad52d116">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.259565888566 139.73778731957597 17.918 35.259568287349126 139.7377771288163 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1b006317-61d3-4abc-8557-cece8b9fe0a7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_033c7415-e9df-4661-b908-01929e4c59ce">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.259568287349126 139.7377771288163 17.918 35.25957327228259 139.7377657151043 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_abd9f212-fc9e-479a-8e57-ca60991bc16c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ef67e4f3-6118-43ba-b787-edce5df85d65">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.25957327228259 139.7377657151043 17.918 35.259579546768606 139.7377549373104 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_afc681e2-a201-4088-9c0d-bb97966c1e1b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8b88ed98-670c-44aa-a939-d6d545639bde">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.259579546768606 139.7377549373104 17.918 35.25961723077406 139.73762268148525 17.918 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5f8d6ba3-c8bc-45be-a8cc-9cbfc80daefd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8c6efe57-a9f1-4e0c-8858-1af4228569a9">
													<gml:posList>35.259579546768606 139.7377549373104 17.918 35.25958721923983 139.73774512501384 17.918 35.25961723077406 139.73762268148525 17.918 35.259579546768606 139.7377549373104 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f58a217d-87ea-43b6-a8ed-412e0f88cbf2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5a2eb0e1-6d62-4775-9821-4f1017b19385">
													<gml:posList>35.25958721923983 139.73774512501384 17.918 35.25959474983381 139.73773829123564 17.918 35.25961723077406 139.73762268148525 17.918 35.25958721923983 139.73774512501384 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3a9b5049-6045-4076-946a-6cca0147415e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_74bf61a5-5b3c-4aa4-9f00-c7987d07aece">
													<gml:posList>35.25959474983381 139.73773829123564 17.918 35.259604344979664 139.73773179572896 17.918 35.25961723077406 139.73762268148525 17.918 35.25959474983381 139.73773829123564 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a8394ee1-8ac6-4ace-8e0a-ef33ea2ce3ca">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d0d1eff8-102f-43c1-9eb8-22bbc2bb4d55">
													<gml:posList>35.259604344979664 139.73773179572896 17.918 35.259612364222654 139.7377273352654 17.918 35.25961723077406 139.73762268148525 17.918 35.259604344979664 139.73773179572896 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e9ffbb05-daab-4e19-8e13-43d09a222780">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dee47474-dc13-4b60-bf40-1008a9592529">
													<gml:posList>35.259612364222654 139.7377273352654 17.918 35.25962115129924 139.7377249180835 17.918 35.25961723077406 139.73762268148525 17.918 35.259612364222654 139.7377273352654 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5013c281-93b7-4007-becf-fea3ef4926de">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_57f072e2-1156-483e-96fb-3938e8fe1f1a">
													<gml:posList>35.25962115129924 139.7377249180835 17.918 35.25963146367433 139.73772487300138 17.918 35.25961723077406 139.73762268148525 17.918 35.25962115129924 139.7377249180835 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ce817ec4-7216-45e8-87cf-ced17bde95a5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_106c683a-efed-40c8-bd7d-90110f237fd2">
													<gml:posList>35.2596427960501 139.7377265741697 17.918 35.25961723077406 139.73762268148525 17.918 35.25963146367433 139.73772487300138 17.918 35.2596427960501 139.7377265741697 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_520f58f5-8f2a-4725-84b2-73fafb888bb8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_32853050-88f2-4765-a8a0-8fb83841f7d2">
													<gml:posList>35.25965540144442 139.73773080159927 17.918 35.25961723077406 139.73762268148525 17.918 35.2596427960501 139.7377265741697 17.918 35.25965540144442 139.73773080159927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c1bb30d5-a528-494e-a112-6906337d37a5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0ea7f73f-0921-404f-954b-aab6d6e5af6f">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25961723077406 139.73762268148525 17.918 35.25968777805937 139.7377613494349 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5f81b7d9-baef-4e8d-8fd0-750b9b94040f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2fa45614-a241-4e6c-935f-edf05c5ac451">
													<gml:posList>35.259673610879936 139.7377427925526 17.918 35.25961723077406 139.73762268148525 17.918 35.259666051699966 139.73773626223345 17.918 35.259673610879936 139.7377427925526 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_84c2c933-fe45-4cb3-8e8d-1b0f60f1059c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_18a53b51-e14b-4dc6-9a0c-47e2f8557d1b">
													<gml:posList>35.259681398031 139.73775263066943 17.918 35.25961723077406 139.73762268148525 17.918 35.259673610879936 139.7377427925526 17.918 35.259681398031 139.73775263066943 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5781aec0-bf19-4a3b-9113-7b9832ad65bd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e51ae5a2-0d3f-4c56-95d0-6604181f1efc">
													<gml:posList>35.25968777805937 139.7377613494349 17.918 35.25961723077406 139.73762268148525 17.918 35.259681398031 139.73775263066943 17.918 35.25968777805937 139.7377613494349 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_80f386e2-504f-4762-b022-94326ca604bd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_027a14d1-6714-407d-adec-8e30ecc2a096">
													<gml:posList>35.25982030831789 139.73791156265102 17.918 35.25968777805937 139.7377613494349 17.918 35.2596947741605 139.7377739909971 17.918 35.25982030831789 139.73791156265102 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8b1f9ee6-5456-41bb-b9e4-178395706608">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ca40a079-0d2b-4e74-9152-dd0f2e1408c0">
													<gml:posList>35.25980821523928 139.73790542227852 17.918 35.2596947741605 139.7377739909971 17.918 35.25969742999061 139.7377810985704 17.918 35.25980821523928 139.73790542227852 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b94e558d-4fc0-4639-8bda-c04a49b61877">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_beb079ca-b90f-4ad6-9634-bd66267d9e09">
													<gml:posList>35.25980821523928 139.73790542227852 17.918 35.25969742999061 139.7377810985704 17.918 35.259700330326815 139.73778962359927 17.918 35.25980821523928 139.73790542227852 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b00f515f-5bc8-438e-8e80-7b64b2555331">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aafa8252-aba3-4668-9ea2-210272cadbab">
													<gml:posList>35.259803301117174 139.73790376850937 17.918 35.259700330326815 139.73778962359927 17.918 35.259702582237566 139.73779891870717 17.918 35.259803301117174 139.73790376850937 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0ea68d7b-74a9-4357-8431-9b3b2bd01732">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9f41a6cd-6239-430a-a72d-fa068da51161">
													<gml:posList>35.25979150052736 139.7379027382679 17.918 35.259702582237566 139.73779891870717 17.918 35.25970329143802 139.73780662203973 17.918 35.25979150052736 139.7379027382679 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c54b05de-0847-4daa-83fb-82bb661e0159">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9a74ade2-647c-4508-9b61-cb70381af371">
													<gml:posList>35.25978517302655 139.73790346005242 17.918 35.25970329143802 139.73780662203973 17.918 35.25970358105886 139.7378195132624 17.918 35.25978517302655 139.73790346005242 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_51b96af0-5913-4e81-ae22-c1a360660866">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_26f585a0-9032-4321-b27b-72978ee90140">
													<gml:posList>35.25973399693007 139.73791278482804 17.918 35.25970358105886 139.7378195132624 17.918 35.25970045201622 139.73787528145706 17.918 35.25973399693007 139.73791278482804 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_00ec4f41-8128-4164-9845-b06fcdcbba68">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b05b8a18-0a70-4072-8a56-57340be9b7d1">
													<gml:posList>35.25973399693007 139.73791278482804 17.918 35.25970045201622 139.73787528145706 17.918 35.25970101883761 139.7378853368703 17.918 35.25973399693007 139.73791278482804 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ce9eebf3-294d-4aec-af10-29cb6a780a88">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c3c29f24-0db5-4e5a-8744-ab4986c15ffc">
													<gml:posList>35.25967066445761 139.7380758993473 17.918 35.25977880916527 139.73802961371203 17.918 35.25970529952417 139.73797537496668 17.918 35.25967066445761 139.7380758993473 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a4e3c73c-658d-4d75-ba91-7c43a24bc572">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c1a8403a-a83c-41cd-9e46-d41b022cf486">
													<gml:posList>35.25970579949657 139.7379006406829 17.918 35.25970101883761 139.7378853368703 17.918 35.25970250365558 139.73789353385533 17.918 35.25970579949657 139.7379006406829 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_275e2e92-0969-4223-9fff-da72427b9b02">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_42d9ff90-9c12-461b-87e0-0c7f9ed7a604">
													<gml:posList>35.25970937292682 139.73790539527212 17.918 35.25970101883761 139.7378853368703 17.918 35.25970579949657 139.7379006406829 17.918 35.25970937292682 139.73790539527212 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cee7d502-5750-4f4f-a89f-fbf8ea11e9c4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8651edb4-8dcb-4cb1-82bf-4714d7cacd87">
													<gml:posList>35.25972734499969 139.73791361689402 17.918 35.25970101883761 139.7378853368703 17.918 35.25970937292682 139.73790539527212 17.918 35.25972734499969 139.73791361689402 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a62ad579-b83c-405d-bda9-0ed17937fc2f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ed6c56ef-ff32-44f9-9cf2-26fa5f17fb0f">
													<gml:posList>35.25972734499969 139.73791361689402 17.918 35.25970937292682 139.73790539527212 17.918 35.25971373011884 139.73790953348902 17.918 35.25972734499969 139.73791361689402 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9c243e31-f174-4253-8383-beef1255e5f4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c45afd69-a4f2-4fc7-80e8-6989db19f355">
													<gml:posList>35.2597223418349 139.7379133589924 17.918 35.25971373011884 139.73790953348902 17.918 35.2597173468958 139.73791210096826 17.918 35.2597223418349 139.7379133589924 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c5bd6b67-c1ca-4ead-9985-34f28c6d51e3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f9afbf12-9ced-4bbe-844a-a0d44d88f315">
													<gml:posList>35.25972734499969 139.73791361689402 17.918 35.25971373011884 139.73790953348902 17.918 35.2597223418349 139.7379133589924 17.918 35.25972734499969 139.73791361689402 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6796f664-5f23-41a9-9e33-5b0169bdf085">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3b83dc51-db1d-4410-ae43-8b288cb7e7f3">
													<gml:posList>35.25972734499969 139.73791361689402 17.918 35.25973399693007 139.73791278482804 17.918 35.25970101883761 139.7378853368703 17.918 35.25972734499969 139.73791361689402 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_70752af7-4f9e-4232-8897-0eb99c4d782d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_643c1c9b-748a-482a-82df-3334c74287b1">
													<gml:posList>35.25973399693007 139.73791278482804 17.918 35.25978517302655 139.73790346005242 17.918 35.25970358105886 139.7378195132624 17.918 35.25973399693007 139.73791278482804 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_eba57495-4d7f-4dd6-ac95-f1d5faa200e8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a7e28453-d4dd-4914-b8fe-f63c7704058f">
													<gml:posList>35.25978517302655 139.73790346005242 17.918 35.25979150052736 139.7379027382679 17.918 35.25970329143802 139.73780662203973 17.918 35.25978517302655 139.73790346005242 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_149700e1-a9f4-45ad-9382-64a6b5459ec5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fad2d9c7-0678-48d7-84a9-e43046a5cd2e">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25968152899156 139.7381259186416 17.918 35.259622516203756 139.73821140379226 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_221b48bd-80f2-4de3-a6ab-36dfe1c43191">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b0ea3b56-9526-45b2-9b29-e801e67f302f">
													<gml:posList>35.25979732391873 139.73790289629525 17.918 35.259702582237566 139.73779891870717 17.918 35.25979150052736 139.7379027382679 17.918 35.25979732391873 139.73790289629525 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c5d10f38-f963-4c40-a854-65d2dbc2fc6a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_955bf34c-360e-4c7b-a9b7-db806456a2f6">
													<gml:posList>35.259803301117174 139.73790376850937 17.918 35.259702582237566 139.73779891870717 17.918 35.25979732391873 139.73790289629525 17.918 35.259803301117174 139.73790376850937 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e76eb4a2-dace-4e88-90ef-0d98ceee4eb5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2d375df6-a711-4a23-a6eb-05e4576e55e7">
													<gml:posList>35.25980821523928 139.73790542227852 17.918 35.259700330326815 139.73778962359927 17.918 35.259803301117174 139.73790376850937 17.918 35.25980821523928 139.73790542227852 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2737265f-71cd-4bb8-a17b-3967c1d4748e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d6b9eb81-5a2f-467e-b831-cebd145dffe6">
													<gml:posList>35.25981377002061 139.73790788857642 17.918 35.2596947741605 139.7377739909971 17.918 35.25980821523928 139.73790542227852 17.918 35.25981377002061 139.73790788857642 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ae405ac2-a567-4894-ba11-ecb22e2d1a95">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c66a47d0-88eb-41c2-be4e-d1bfc6e7a8d8">
													<gml:posList>35.25982030831789 139.73791156265102 17.918 35.2596947741605 139.7377739909971 17.918 35.25981377002061 139.73790788857642 17.918 35.25982030831789 139.73791156265102 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0f94d92c-e0b8-40e7-8f9e-62ecfda19049">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_414070a6-747f-46e9-b576-04ebc0a32a19">
													<gml:posList>35.25982691936237 139.7379160389303 17.918 35.25968777805937 139.7377613494349 17.918 35.25982030831789 139.73791156265102 17.918 35.25982691936237 139.7379160389303 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b00018d6-e25e-49d3-91e9-b141d08dbf35">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_661159c8-74d3-408f-9b8f-66febb7111b3">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25968777805937 139.7377613494349 17.918 35.25982691936237 139.7379160389303 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_707edbc9-196a-4f0e-ac3b-6752661f1cfe">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7dabecd5-29db-4ece-bf66-c91eeca165eb">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25982691936237 139.7379160389303 17.918 35.25983115028391 139.73792008937957 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1326e97a-337c-4a2e-afd1-193ee43951e1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b775507a-9f16-4dd4-a25e-54ba6246557d">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25983115028391 139.73792008937957 17.918 35.25983513867611 139.73792522814998 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b8fe10c3-359c-4341-9c23-9028e74fd03f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_edccfcf2-bc08-4404-ab89-dc44b947d6f3">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25983513867611 139.73792522814998 17.918 35.259838866050906 139.7379308727791 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_db9aa8c9-37d6-4dc0-8b7e-f1aad68ec1d9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_59431013-a1d7-468a-8c4d-f87d8d918fb1">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.259838866050906 139.7379308727791 17.918 35.25984210640868 139.73793621025192 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ee205f0b-c70d-4e52-9afe-046c520b3a4c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4d48c9f7-cc71-498c-9702-355280b14706">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25984210640868 139.73793621025192 17.918 35.25984429113582 139.73794034003262 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7372670d-33bb-4b0f-9445-d924391eb981">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_40ed30ec-5ccc-471e-99b6-6d8078c4e273">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25984429113582 139.73794034003262 17.918 35.259846702555414 139.73794616204933 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_104d4d1f-269f-4800-9f12-6aa0e0f3919c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d721ce82-c8b8-4a8c-bf2c-a3bd98ef5148">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.259846702555414 139.73794616204933 17.918 35.259848384125355 139.7379523805712 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a4e50b3c-450a-412d-be8d-074d15a0715c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_de96251c-2207-4c49-842c-424ede1fb456">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.259848384125355 139.7379523805712 17.918 35.25984948869948 139.7379585008569 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_90d745a7-fdcc-4a51-b8e6-3f0ed78f3ee1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_13b1cd5f-8fb1-4b7d-9a74-e2cfd425aff4">
													<gml:posList>35.25995567900424 139.73797199382997 17.918 35.25984948869948 139.7379585008569 17.918 35.25984999934051 139.73796590770004 17.918 35.25995567900424 139.73797199382997 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1a9706cb-cc82-46f8-8782-ba1678d1ae8a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_25d7fd64-025c-4d41-9782-f4b68cffe589">
													<gml:posList>35.25984865931544 139.7379812956465 17.918 35.25995567900424 139.73797199382997 17.918 35.259850023986424 139.73797430423687 17.918 35.25984865931544 139.7379812956465 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_13b33c66-d0c0-44be-a524-32783b6a9fa7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_78a3ad37-624e-49d3-b9c0-687a09f0e003">
													<gml:posList>35.2598467011007 139.73799006817467 17.918 35.25995567900424 139.73797199382997 17.918 35.25984865931544 139.7379812956465 17.918 35.2598467011007 139.73799006817467 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_af65b63b-3172-49d8-9272-398563315af6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_62950ab1-2bc1-428b-bd44-850bbd8be7b3">
													<gml:posList>35.25984435330329 139.7379963463677 17.918 35.25995567900424 139.73797199382997 17.918 35.2598467011007 139.73799006817467 17.918 35.25984435330329 139.7379963463677 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b7702df6-9f41-4eab-b81c-0600343a6c9d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f683cb26-b2d8-4341-a8b3-e27c0d33331d">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25995567900424 139.73797199382997 17.918 35.25981959722873 139.73802726899535 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9525ceb9-20fb-4486-b4c9-5b90cd9a3b29">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8b586749-03e9-4279-835b-8b7f263de3c6">
													<gml:posList>35.25984094211692 139.738003010465 17.918 35.25995567900424 139.73797199382997 17.918 35.25984435330329 139.7379963463677 17.918 35.25984094211692 139.738003010465 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f2d1fbf9-c53d-4390-a2b0-20465c69b3ca">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f78104c3-1526-428c-987a-e52fcfbf4a35">
													<gml:posList>35.259837124730936 139.73800897166032 17.918 35.25995567900424 139.73797199382997 17.918 35.25984094211692 139.738003010465 17.918 35.259837124730936 139.73800897166032 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_39c065f0-e7d8-46bd-bf64-9be65f6549da">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_28f79406-7728-4404-a0f8-8309e2f1c8f7">
													<gml:posList>35.25983322612906 139.73801482304748 17.918 35.25995567900424 139.73797199382997 17.918 35.259837124730936 139.73800897166032 17.918 35.25983322612906 139.73801482304748 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_97ee9962-8c43-4182-b00b-925e25eacd13">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1034c6c4-1886-463d-87ef-368255cc41bf">
													<gml:posList>35.259829830607025 139.738018486782 17.918 35.25995567900424 139.73797199382997 17.918 35.25983322612906 139.73801482304748 17.918 35.259829830607025 139.738018486782 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_556113a6-b451-48f2-ae3b-3159b5e586f4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_576d0840-51a4-47ee-9a4f-aaf703172e6f">
													<gml:posList>35.259824461949364 139.73802342769727 17.918 35.25995567900424 139.73797199382997 17.918 35.259829830607025 139.738018486782 17.918 35.259824461949364 139.73802342769727 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fbab0154-27ed-49f7-859f-3b12c9d72974">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a3582b27-91b2-42ac-9c86-9035c638950d">
													<gml:posList>35.25981959722873 139.73802726899535 17.918 35.25995567900424 139.73797199382997 17.918 35.259824461949364 139.73802342769727 17.918 35.25981959722873 139.73802726899535 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a2c5b4de-4b31-40a7-b52e-6f863fab5b4d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_afc2d898-e446-4e22-ad34-e68d9b30410a">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25981959722873 139.73802726899535 17.918 35.259814731728945 139.7380301211701 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a860893d-87b3-466a-8703-e1495268ed7a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_98ece9e8-d46f-4645-861e-a5ddfd5a153f">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.259814731728945 139.7380301211701 17.918 35.25980921702374 139.73803275429924 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9ac2f47b-c10e-485e-9213-8f217a427872">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c0657c2e-7875-4bd7-9c0c-9a09b15e062a">
													<gml:posList>35.259658939727075 139.73798805706116 17.918 35.25966688303696 139.73797873902072 17.918 35.259662676381495 139.73798260152373 17.918 35.259658939727075 139.73798805706116 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d5107499-9da7-4c8f-bb7a-89077c2b22c3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_14ad4c9e-7314-42d3-8d0d-57d0dc9c7b95">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25980921702374 139.73803275429924 17.918 35.25980395362932 139.7380340023607 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_53c9433d-c65e-40b9-a7ea-98dad953e78d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f89056ef-ebce-4ed3-96bd-efd663dc9077">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25980395362932 139.7380340023607 17.918 35.25979755354563 139.73803413074594 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ef3a34d2-f255-4a18-aa90-59d15c4f0a5c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4d3f046a-0916-40c7-84b6-7105b19189c2">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25979755354563 139.73803413074594 17.918 35.259790675061595 139.73803344641183 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_56d42a0f-8242-4edf-a9c8-e8ad7ae91136">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4ac435af-e78f-4300-877d-97c81a4e2680">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25978477852568 139.73803198061987 17.918 35.25977880916527 139.73802961371203 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cdbcabcf-0871-4a30-aaa4-a47933f39ba4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a3de2495-b71e-4374-855c-db0b2d7c720f">
													<gml:posList>35.25970529952417 139.73797537496668 17.918 35.259699744354364 139.73797241410668 17.918 35.25969377546042 139.73797064067853 17.918 35.25970529952417 139.73797537496668 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4a6a32ae-38cb-451f-8589-ee637c5309cd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_05082397-1e46-46f7-b539-bd97e6826420">
													<gml:posList>35.25970529952417 139.73797537496668 17.918 35.25969377546042 139.73797064067853 17.918 35.25967792936525 139.7379720659927 17.918 35.25970529952417 139.73797537496668 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d85f1e77-a5af-432a-b09b-e1264e17d410">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f43653f8-6ce7-4d76-ab19-5b11485ededa">
													<gml:posList>35.25967792936525 139.7379720659927 17.918 35.25969377546042 139.73797064067853 17.918 35.25968885319091 139.737970085942 17.918 35.25967792936525 139.7379720659927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2d8ae0be-82a4-4e8c-bf4f-4e017309b649">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_af80b3ed-9904-4c5f-94e3-9266a7b579dd">
													<gml:posList>35.25967792936525 139.7379720659927 17.918 35.25968885319091 139.737970085942 17.918 35.25968359802319 139.7379703338836 17.918 35.25967792936525 139.7379720659927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b0101c68-426e-4dc8-b8dc-3cb37cb09e31">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c3feb39c-a9ab-40dd-ac3e-f9017dfaa416">
													<gml:posList>35.259652466124535 139.73800928680149 17.918 35.25970529952417 139.73797537496668 17.918 35.25967792936525 139.7379720659927 17.918 35.259652466124535 139.73800928680149 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f7f36b4c-2397-4130-bbc3-37e2c825423e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bdbe0a51-90a7-419e-b84f-f0314b212425">
													<gml:posList>35.25966688303696 139.73797873902072 17.918 35.25967792936525 139.7379720659927 17.918 35.25967126129378 139.7379752939456 17.918 35.25966688303696 139.73797873902072 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ea7af8e4-c86b-45eb-bd70-361d6b2fede4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9616493a-4f0d-4612-a4ce-dc7f8d8b86bb">
													<gml:posList>35.259652466124535 139.73800928680149 17.918 35.25967792936525 139.7379720659927 17.918 35.25966688303696 139.73797873902072 17.918 35.259652466124535 139.73800928680149 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b4905989-1545-4883-b534-71393c1ee024">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6f994f2a-55c4-4b81-85ee-b52ab59cba59">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.259790675061595 139.73803344641183 17.918 35.25978477852568 139.73803198061987 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2c0d9e58-6c44-4f2b-bf4e-7524cb5c2277">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f6942a6d-a0ab-4010-81d2-f25513b45925">
													<gml:posList>35.259652466124535 139.73800928680149 17.918 35.25966688303696 139.73797873902072 17.918 35.259658939727075 139.73798805706116 17.918 35.259652466124535 139.73800928680149 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_568fed17-f12b-4355-b39a-70f2825d0dd1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5c98a1a7-1125-43c6-85f9-2d22c58bd22e">
													<gml:posList>35.25965435017399 139.73799790969406 17.918 35.259658939727075 139.73798805706116 17.918 35.25965619403464 139.73799273113025 17.918 35.25965435017399 139.73799790969406 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8ee4f0d3-19c6-4da0-b710-26376ec5b57f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f54949b0-8e13-4fce-8cf9-22d343da0031">
													<gml:posList>35.25965316428178 139.73800298857495 17.918 35.259658939727075 139.73798805706116 17.918 35.25965435017399 139.73799790969406 17.918 35.25965316428178 139.73800298857495 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_73a790f7-1a4c-4fa2-af1d-9545e2dc6b77">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b653d0bf-f987-48be-bc99-63e8af735c14">
													<gml:posList>35.259652466124535 139.73800928680149 17.918 35.259658939727075 139.73798805706116 17.918 35.25965316428178 139.73800298857495 17.918 35.259652466124535 139.73800928680149 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_81f3a852-6683-42cf-8de4-d7c471730da3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_740eba3f-145b-4907-915b-05cd396df553">
													<gml:posList>35.25965208378042 139.73801598030684 17.918 35.25970529952417 139.73797537496668 17.918 35.259652466124535 139.73800928680149 17.918 35.25965208378042 139.73801598030684 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_445729b0-6110-4d4b-9348-d5be400c0b14">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d286dc13-0134-48f3-8cc4-91648b077866">
													<gml:posList>35.25965338261245 139.73802839776027 17.918 35.25970529952417 139.73797537496668 17.918 35.25965208378042 139.73801598030684 17.918 35.25965338261245 139.73802839776027 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_aa8ebbd5-05af-4259-9a6c-946bf48fc57c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_95dac9ac-e6b9-4537-8078-8d9d1a94dbeb">
													<gml:posList>35.25965338261245 139.73802839776027 17.918 35.25965208378042 139.73801598030684 17.918 35.259652440862574 139.73802299166348 17.918 35.25965338261245 139.73802839776027 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e4aad4ca-a98c-4c55-9138-599b8d201455">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2676d737-bd50-44b0-9e37-1fdea00817e0">
													<gml:posList>35.25965537224956 139.7380366271229 17.918 35.25970529952417 139.73797537496668 17.918 35.25965338261245 139.73802839776027 17.918 35.25965537224956 139.7380366271229 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8e6e1f61-b308-42eb-943d-da1481436a57">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_151b7da4-ab5e-4170-8222-4c59b2eccf2f">
													<gml:posList>35.2596575322844 139.73804374627193 17.918 35.25970529952417 139.73797537496668 17.918 35.25965537224956 139.7380366271229 17.918 35.2596575322844 139.73804374627193 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f4ec2c99-3a20-4396-a665-77b694621a4d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5516495b-9b5e-4f82-b194-344e5a23cbf7">
													<gml:posList>35.25967066445761 139.7380758993473 17.918 35.25970529952417 139.73797537496668 17.918 35.2596575322844 139.73804374627193 17.918 35.25967066445761 139.7380758993473 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b86139a7-e6e9-425c-84df-5affdcbc1e22">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_01ba3eb6-328e-40e0-8710-f7863b694234">
													<gml:posList>35.25967249080396 139.73808282106472 17.918 35.25977880916527 139.73802961371203 17.918 35.25967066445761 139.7380758993473 17.918 35.25967249080396 139.73808282106472 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6cbf95ba-d658-42ad-991a-95e53f713c02">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d102aec5-a540-43d4-b0d5-22dd736e733b">
													<gml:posList>35.25967406679861 139.73809234776354 17.918 35.25977880916527 139.73802961371203 17.918 35.25967249080396 139.73808282106472 17.918 35.25967406679861 139.73809234776354 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_14fe6843-eb82-461a-b27f-f8ac9645eb7f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_83248f7c-c3a2-470f-b618-3fc46252cd82">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25977880916527 139.73802961371203 17.918 35.25967406679861 139.73809234776354 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_89529d00-bdcc-4723-9e23-4d212b9abf4e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e1f3b5fc-b1b2-4560-9ee2-1b3f523b56bb">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25967406679861 139.73809234776354 17.918 35.25967385533306 139.73809854650938 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5d49ce32-c3d6-4c89-92ff-bd8143b924a1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5d019dfe-8427-4349-9f9e-b59e97e29a7a">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.25967385533306 139.73809854650938 17.918 35.259673147992196 139.73810463593276 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_533a01a2-1f87-4bf5-96b7-b2b228206b15">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c9cd4f3e-c64f-45ae-9419-b89a15ec7ddb">
													<gml:posList>35.25956536447386 139.73824097683504 17.918 35.25958201919518 139.7381698486745 17.918 35.25953108754047 139.73820553543945 17.918 35.25956536447386 139.73824097683504 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f3ef135f-7731-4fe7-a905-3f523f9d75de">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_43b7f86e-a948-432a-af25-5119c2445d76">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.259673147992196 139.73810463593276 17.918 35.259671872505635 139.73811041829376 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_527d64d2-0a6f-44b6-aad6-686181f0cac4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_adb6afd6-f724-43a0-a40f-070623640134">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.259671872505635 139.73811041829376 17.918 35.259669844540305 139.73811392890445 17.918 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_21604c99-12e8-4868-96c1-6d717bcc2061">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7bc50990-e52c-4856-a735-d72c5cfaaa9e">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25980395362932 139.7380340023607 17.918 35.25968152899156 139.7381259186416 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3ebb2be3-2d5b-4c36-849b-fe055bd3e310">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2d0b8005-741b-4460-bd71-55894b66f6e1">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.259622516203756 139.73821140379226 17.918 35.25956536447386 139.73824097683504 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_83e1f664-f095-45d2-a63c-e8ab844d6880">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_31774431-bb6b-44f8-b76a-b71716b2810d">
													<gml:posList>35.25954861784281 139.73805122622278 17.918 35.25954233187303 139.73804745294183 17.918 35.25953044928078 139.7380453127659 17.918 35.25954861784281 139.73805122622278 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2e8ed472-2e72-4d35-a6c9-8128ca5752c1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1694f1e8-ee37-4ff2-af6a-839041ccbeb8">
													<gml:posList>35.25958201919518 139.7381698486745 17.918 35.259590402061896 139.73815770537246 17.918 35.25958622269745 139.73815378503826 17.918 35.25958201919518 139.7381698486745 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_892b84ae-3bad-4f27-b175-203b4ea94d7d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7dcb09f5-8ffd-4770-8ef2-da68db9cd994">
													<gml:posList>35.25958201919518 139.7381698486745 17.918 35.25958622269745 139.73815378503826 17.918 35.25958135314272 139.73814820968445 17.918 35.25958201919518 139.7381698486745 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c9354a31-fb13-46b4-ac6f-2fd5df506f22">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_690229c0-4a33-45c1-b671-17e24290942f">
													<gml:posList>35.25958201919518 139.7381698486745 17.918 35.25958135314272 139.73814820968445 17.918 35.2595761636311 139.73814024783388 17.918 35.25958201919518 139.7381698486745 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b583acb8-d31a-4a69-9e5a-72131390bf14">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_179c35de-b62a-4f01-a824-e723e203402d">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25958201919518 139.7381698486745 17.918 35.2595761636311 139.73814024783388 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_92ed24d3-0245-4434-9b8e-4071d3082762">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c889f826-6feb-4e65-a761-a3f9f034de2c">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.2595761636311 139.73814024783388 17.918 35.2595731750611 139.7381341187792 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c0e7e7f3-e5b8-4096-b6d1-71581706fd0c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e57f8101-e784-436c-8256-2c6f05213cf4">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.2595731750611 139.7381341187792 17.918 35.25957148518652 139.73812879049305 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a2f47c17-a737-42fa-b022-6c0c47b1bcdc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4c2ee3f3-e3ca-460d-83a4-438e726f26dd">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25957148518652 139.73812879049305 17.918 35.25956967443283 139.7381187695197 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1b1cd7e2-9ecb-4b67-a4ca-5180c139cc60">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a79e0bf5-766e-48a4-8faf-7b9a74161c7c">
													<gml:posList>35.25956967443283 139.7381187695197 17.918 35.259569683415414 139.7381072737272 17.918 35.25953044928078 139.7380453127659 17.918 35.25956967443283 139.7381187695197 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_38551354-97b0-4139-ba60-814e7a98c041">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f0e2f9a5-d2cc-4dd0-b27f-98c4a9f3192c">
													<gml:posList>35.259569683415414 139.7381072737272 17.918 35.25956951320005 139.73809716291348 17.918 35.25953044928078 139.7380453127659 17.918 35.259569683415414 139.7381072737272 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6b0ae0c3-983f-42ce-8984-31755f3cec69">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_90386f34-9fc9-4191-9502-34ac6611cda4">
													<gml:posList>35.25956951320005 139.73809716291348 17.918 35.25956819784299 139.73808664680107 17.918 35.25953044928078 139.7380453127659 17.918 35.25956951320005 139.73809716291348 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0373db23-0da4-4f05-8c75-139e5867a533">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_90f15722-408d-4f58-8990-1b9a181044e6">
													<gml:posList>35.25956819784299 139.73808664680107 17.918 35.25956645200297 139.7380789337016 17.918 35.25953044928078 139.7380453127659 17.918 35.25956819784299 139.73808664680107 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9c2377f0-e864-4542-8ae7-00a9c56ff3d5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e341b8e5-a69f-4a08-9cfa-6f053230a6cf">
													<gml:posList>35.25956645200297 139.7380789337016 17.918 35.259563885996236 139.7380713974059 17.918 35.25953044928078 139.7380453127659 17.918 35.25956645200297 139.7380789337016 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_973b819d-56e1-4709-abe9-d01e1a2e2f60">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_455f6249-e595-4556-89a7-b6a20e922aff">
													<gml:posList>35.259563885996236 139.7380713974059 17.918 35.25956017477023 139.73806335690034 17.918 35.2595552208113 139.738056900443 17.918 35.259563885996236 139.7380713974059 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_239bea49-1c20-47c2-9ba6-e72d47fa29d1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d9c441f0-5087-43c5-a1df-a2f8b2db13c9">
													<gml:posList>35.259563885996236 139.7380713974059 17.918 35.2595552208113 139.738056900443 17.918 35.25954861784281 139.73805122622278 17.918 35.259563885996236 139.7380713974059 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ce785b6c-11c6-41bd-8617-091202c34dd1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_73502fba-b482-4f76-abd7-e044d8ea33c4">
													<gml:posList>35.259563885996236 139.7380713974059 17.918 35.25954861784281 139.73805122622278 17.918 35.25953044928078 139.7380453127659 17.918 35.259563885996236 139.7380713974059 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8b7b05fa-8938-4c15-b49b-449943d3394f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1fecc290-b136-418c-9eaf-d921947ecede">
													<gml:posList>35.25956536447386 139.73824097683504 17.918 35.259622516203756 139.73821140379226 17.918 35.25958201919518 139.7381698486745 17.918 35.25956536447386 139.73824097683504 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_70614227-6d99-4763-abb5-8431d83a7454">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f16d9e7c-91c9-44a9-8c56-0f1902011779">
													<gml:posList>35.25954233187303 139.73804745294183 17.918 35.259536029215894 139.73804538316614 17.918 35.25953044928078 139.7380453127659 17.918 35.25954233187303 139.73804745294183 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_49e96854-5a53-435a-98ff-dcec24957176">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0e5681d7-6ee0-47aa-92ec-9e7eafe3a69e">
													<gml:posList>35.25956967443283 139.7381187695197 17.918 35.25953044928078 139.7380453127659 17.918 35.25947094014199 139.73804984445047 17.918 35.25956967443283 139.7381187695197 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c97e1a88-7049-427f-8a67-0dc702f321a3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1d67afcd-1463-4cf4-bbc1-cfb81d91b9f7">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25956967443283 139.7381187695197 17.918 35.25947094014199 139.73804984445047 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bfd9aaf8-bb0c-4746-b521-587de287f6ee">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ecd61989-4893-4a80-a26e-2fda7f79fa68">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25947094014199 139.73804984445047 17.918 35.25946643254079 139.73804930021555 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9762dad4-99c7-4e05-9966-00bdb024ebe0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d3aee0a3-9c51-4e65-a0de-8c39a5a566a6">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25946643254079 139.73804930021555 17.918 35.25946119421578 139.7380480424719 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c6319706-806e-4d85-9412-7c89bd3d34c4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9dfbb4ec-5c8e-4dca-b1d8-3f64fd785f9e">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25946119421578 139.7380480424719 17.918 35.25945580106328 139.73804477370007 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_11c8075d-b4bf-49b9-8af3-25ffcdfc667f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9af3a614-dfdf-407e-b64d-fc2578ddb417">
													<gml:posList>35.25945580106328 139.73804477370007 17.918 35.25944968558668 139.73804001110494 17.918 35.25934551376892 139.73801401031633 17.918 35.25945580106328 139.73804477370007 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_171081e7-39a1-40a8-a1f5-ba28ca8373b3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bd64e22f-dc85-4ae6-b511-39a177abb1cc">
													<gml:posList>35.25944968558668 139.73804001110494 17.918 35.25944512952094 139.73803515876335 17.918 35.25934551376892 139.73801401031633 17.918 35.25944968558668 139.73804001110494 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_81546ebe-2f17-459c-aeee-5ab99fadfc9d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_973c8af9-c3a8-4f05-9f3c-6813e3938bc3">
													<gml:posList>35.25944512952094 139.73803515876335 17.918 35.2594411495849 139.7380293056383 17.918 35.25934551376892 139.73801401031633 17.918 35.25944512952094 139.73803515876335 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e41fb53e-f5e4-4145-b0e3-96c10b56f417">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5f23958a-63fb-4114-a228-41beb73b3658">
													<gml:posList>35.2594411495849 139.7380293056383 17.918 35.25943743820023 139.73802106732313 17.918 35.25934551376892 139.73801401031633 17.918 35.2594411495849 139.7380293056383 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_083523c2-2033-4d28-89a9-3da1ada56092">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d63a8079-8c5e-4337-982b-12b48ee7bb7a">
													<gml:posList>35.25943743820023 139.73802106732313 17.918 35.25943561145207 139.73801364007775 17.918 35.25934551376892 139.73801401031633 17.918 35.25943743820023 139.73802106732313 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3873cbfb-a075-4e15-a667-042b7e535132">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4397cc5f-807f-43b5-aa89-f3b320f71c70">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.25944173734013 139.7379744088309 17.918 35.259443288515165 139.7378731949204 17.918 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c15c7f65-573c-4a2c-b164-f832a76cd21d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_904eba77-d439-4bcd-942c-6c385eb4ba59">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.259436261819964 139.7379924501849 17.918 35.25943863437416 139.73798327057784 17.918 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_448e5c40-5d1f-4dfc-8894-91b213551844">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b360ec9f-42f4-478f-87a5-39b8244daf38">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.259458495171664 139.73789457825012 17.918 35.259453151376654 139.73788531976322 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9c1ceacf-3246-4f51-95e5-f0f839c79c94">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0d4d66c0-0894-4bba-915f-689907e9bb1e">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.25943863437416 139.73798327057784 17.918 35.25944173734013 139.7379744088309 17.918 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_451f29c4-1e20-4045-b66b-4e3a2ecc6725">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c99072ca-5ae5-4b47-ac92-c582ad27490e">
													<gml:posList>35.25944173734013 139.7379744088309 17.918 35.25946221354603 139.73793453431927 17.918 35.25945047141383 139.73788189395822 17.918 35.25944173734013 139.7379744088309 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c9da3e04-f125-459a-a819-f40b74709ad8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ab3f0df9-70ed-481d-908c-e8f2d42426e3">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.25946421981807 139.73792955339982 17.918 35.25946483731876 139.73792385974363 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3854aaa6-f6b4-4ce9-9bdf-dd258496d90f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9bf707b1-fd57-48ab-a4ea-dc42c68cd962">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.25946483731876 139.73792385974363 17.918 35.25946505755575 139.73791736426713 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0546d3a3-f76d-48e2-a0c0-9282476d35d7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_798d7baf-7346-4ad2-95cb-8a27c2bf80f2">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.25946505755575 139.73791736426713 17.918 35.25946380654012 139.7379084416772 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e9979ff4-4e58-4144-8c8a-7eaf01ddc839">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8653d082-5266-4d6c-baa5-605639ddf76d">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.25946380654012 139.7379084416772 17.918 35.259461962943824 139.7379025201114 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_48eb8cca-b476-4d47-8262-e9cbcca2eed3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_685e027e-b709-4723-965f-9dd1067ff9a2">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.259461962943824 139.7379025201114 17.918 35.259458495171664 139.73789457825012 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5b4f1981-98ca-40a5-85d3-c3cd678bd5d0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9ef9c9b9-fed8-496a-b9a6-30c5346640d6">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.25943511679936 139.73800363956292 17.918 35.259436261819964 139.7379924501849 17.918 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ff6a22d3-5256-4ca3-a983-ad44a3345ba3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fc9a1069-df06-490e-a7fd-0238a08651b3">
													<gml:posList>35.25946221354603 139.73793453431927 17.918 35.259453151376654 139.73788531976322 17.918 35.25945047141383 139.73788189395822 17.918 35.25946221354603 139.73793453431927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b8a05c2e-6bb0-4c1f-948b-40bff3636e07">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a6f0c9e8-a63e-4fdd-802e-2e0c3b497144">
													<gml:posList>35.25944173734013 139.7379744088309 17.918 35.25945047141383 139.73788189395822 17.918 35.259443288515165 139.7378731949204 17.918 35.25944173734013 139.7379744088309 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d3c2b704-8137-47fb-a9e2-b93cc6141614">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0656680d-1aca-4a4c-b6d1-4a3e9f0e67ed">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.25943561145207 139.73801364007775 17.918 35.25943511679936 139.73800363956292 17.918 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0750dc35-6555-4393-b2b0-3b8c0f867944">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4bbc9e66-d9d9-4f2f-860b-cba4faafd38f">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25945580106328 139.73804477370007 17.918 35.25934551376892 139.73801401031633 17.918 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e2b644c4-805a-499d-97fd-da56c8006ac3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5440379b-ab4a-4f9f-beee-5fba5e4964ee">
													<gml:posList>35.259622516203756 139.73821140379226 21.72735546832999 35.25968152899156 139.7381259186416 21.72735546832999 35.25964103195404 139.7380843635364 21.72735546832999 35.25958201919518 139.7381698486745 21.72735546832999 35.259622516203756 139.73821140379226 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_22fa3183-27a5-404b-9f5b-eb9d85a2ef06">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fb9b46da-4942-4195-95f9-eae6ea5fa879">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.259453151376654 139.73788531976322 19.4009 35.259458495171664 139.73789457825012 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3183e795-0cc4-4be9-9407-8b3c29890cb1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_96f2780e-2091-4d52-8dec-cefa000dcd1b">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.259461962943824 139.7379025201114 19.4009 35.25946380654012 139.7379084416772 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_aee1219a-a0f6-42ed-9ab7-d91da85354ac">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_72cbc479-21bc-41d9-8025-f984343fbee4">
													<gml:posList>35.2594409612081 139.73787037637467 19.4009 35.259424720521174 139.73780584990573 19.4009 35.259404996429865 139.73783449243757 19.4009 35.2594409612081 139.73787037637467 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d5d30b3d-b655-41ed-b259-d87de49039ed">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_640def6f-73aa-4d74-9dc0-7e22d27eaab9">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.259424720521174 139.73780584990573 19.4009 35.2594409612081 139.73787037637467 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_58beebce-6101-4107-b036-ee4a2176080a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5942a48b-23ed-42dd-a439-aa922f73ce60">
													<gml:posList>35.25946221354603 139.73793453431927 19.4009 35.25954306425423 139.7379244274751 19.4009 35.25952795504885 139.73791152067759 19.4009 35.25946221354603 139.73793453431927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6c1b8f8b-c029-4b9b-955d-23d5495fcb7a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bbf66415-c092-4c52-9ccb-5f2cf63fcad3">
													<gml:posList>35.25946221354603 139.73793453431927 19.4009 35.25952795504885 139.73791152067759 19.4009 35.25946421981807 139.73792955339982 19.4009 35.25946221354603 139.73793453431927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d927f905-d812-4d20-bd0d-5084c3b661f3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ff8b5c0b-33d7-48df-b3fc-0b7fa3382664">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.25946221354603 139.73793453431927 19.4009 35.25944173734013 139.7379744088309 19.4009 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e8659a48-f0e6-48f6-adea-b8e0c8cc1850">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6b8ebfc6-921f-4da8-b74e-92d376c65ca9">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.25944173734013 139.7379744088309 19.4009 35.25943863437416 139.73798327057784 19.4009 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_34d3fcd8-ea07-4d5e-bc27-8bda13c045cd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fd87a68e-6b0d-4efa-b6b1-c7591f05103a">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.25943863437416 139.73798327057784 19.4009 35.259436261819964 139.7379924501849 19.4009 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5900fdbf-3933-417d-8e15-6bb0e50f2995">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_499313c7-7918-48b4-9b27-0187b9f0b7dc">
													<gml:posList>35.25944968558668 139.73804001110494 19.4009 35.259436261819964 139.7379924501849 19.4009 35.25943511679936 139.73800363956292 19.4009 35.25944968558668 139.73804001110494 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_41a93a3d-bc81-438b-a26f-af6318f2eaa0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a1fe2056-faeb-4bd3-ace5-037bafa0f744">
													<gml:posList>35.25943743820023 139.73802106732313 19.4009 35.25943511679936 139.73800363956292 19.4009 35.25943561145207 139.73801364007775 19.4009 35.25943743820023 139.73802106732313 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_464d0d47-55e0-4ea1-b1ee-069810237061">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_79160efb-61ed-40cb-bd0a-ae93d428185a">
													<gml:posList>35.25954233187303 139.73804745294183 19.4009 35.259580504322734 139.73795172729461 19.4009 35.25956587536673 139.73794197411962 19.4009 35.25954233187303 139.73804745294183 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e3c3f70b-8c07-4108-b5da-f645aecb8831">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_11fcb7fa-b9fc-44f8-a72c-ac72521cfbf7">
													<gml:posList>35.2594411495849 139.7380293056383 19.4009 35.25943511679936 139.73800363956292 19.4009 35.25943743820023 139.73802106732313 19.4009 35.2594411495849 139.7380293056383 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3c33fd31-c1c5-46ee-8cb1-6c95a3ac8f69">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f1c19a55-dee8-42ec-896c-f8c1eada292d">
													<gml:posList>35.25946483731876 139.73792385974363 19.4009 35.25952795504885 139.73791152067759 19.4009 35.25946505755575 139.73791736426713 19.4009 35.25946483731876 139.73792385974363 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_52c96932-e287-4a12-adaa-50d4121fa47a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c820da03-544e-47de-924e-d1c44e3ff9de">
													<gml:posList>35.25944512952094 139.73803515876335 19.4009 35.25943511679936 139.73800363956292 19.4009 35.2594411495849 139.7380293056383 19.4009 35.25944512952094 139.73803515876335 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f4d1e5e3-ca5f-49b5-9b5b-3ba12f27d7ce">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a38399cf-7c0e-404a-8faf-c9e2c9f22bfd">
													<gml:posList>35.25946505755575 139.73791736426713 19.4009 35.25952795504885 139.73791152067759 19.4009 35.25946380654012 139.7379084416772 19.4009 35.25946505755575 139.73791736426713 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_91d30cca-4fae-4532-903e-9e6e8d6bc5bd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9267d240-f00e-4b0f-b097-57d9f0d8764d">
													<gml:posList>35.25944968558668 139.73804001110494 19.4009 35.25943511679936 139.73800363956292 19.4009 35.25944512952094 139.73803515876335 19.4009 35.25944968558668 139.73804001110494 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_90223125-53be-4f23-b86b-b075329bc6d8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_00b50228-f139-497f-8f99-44fcaeb5ed0f">
													<gml:posList>35.25946421981807 139.73792955339982 19.4009 35.25952795504885 139.73791152067759 19.4009 35.25946483731876 139.73792385974363 19.4009 35.25946421981807 139.73792955339982 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_78d1c873-e963-4b04-94b9-984950db3e50">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_df57d64f-a9df-47c4-841a-1aa16822d768">
													<gml:posList>35.25945580106328 139.73804477370007 19.4009 35.259436261819964 139.7379924501849 19.4009 35.25944968558668 139.73804001110494 19.4009 35.25945580106328 139.73804477370007 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_400ede14-accd-4fab-9b47-d3e6769d5f39">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1d172b5f-526d-4693-bcfe-e3fe9084d5bc">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.259436261819964 139.7379924501849 19.4009 35.25945580106328 139.73804477370007 19.4009 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e2e87abe-b4f4-411c-97c3-7c85c86d28ef">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_114624a4-6200-4159-9f0d-8ec7f18f10e4">
													<gml:posList>35.25946643254079 139.73804930021555 19.4009 35.25945580106328 139.73804477370007 19.4009 35.25946119421578 139.7380480424719 19.4009 35.25946643254079 139.73804930021555 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_75d1542c-52c0-4302-8bae-47a2a9370ba9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_384211dd-10f9-4893-ad92-c19cdbc0686a">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.25945580106328 139.73804477370007 19.4009 35.25946643254079 139.73804930021555 19.4009 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a6f54169-2d9a-438a-987b-665801a673c0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_766431cb-b02a-4494-bf39-8a3f82d2f01d">
													<gml:posList>35.25953044928078 139.7380453127659 19.4009 35.25954306425423 139.7379244274751 19.4009 35.25946221354603 139.73793453431927 19.4009 35.25947094014199 139.73804984445047 19.4009 35.25953044928078 139.7380453127659 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a620c3db-fcc5-4f44-bd5b-ec06d225702b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5197cbdf-1561-417b-8ee1-b2edbc083f43">
													<gml:posList>35.25956017477023 139.73806335690034 19.4009 35.25959506323896 139.7379526773771 19.4009 35.25958757311341 139.7379536862642 19.4009 35.25956017477023 139.73806335690034 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ec531dac-3b0c-404c-8ed4-6008bb5f59f7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_71ace359-ccb7-47b5-94f0-92a01456137c">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.259458495171664 139.73789457825012 19.4009 35.259461962943824 139.7379025201114 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ac45fe4f-783b-4b5d-9d21-53504a59b12a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bace27af-83d1-407b-81f0-ce45ef294dde">
													<gml:posList>35.259536029215894 139.73804538316614 19.4009 35.25956587536673 139.73794197411962 19.4009 35.25953044928078 139.7380453127659 19.4009 35.259536029215894 139.73804538316614 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4056951b-e33b-4909-9cb2-719dc6d5c103">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3e6bbc91-b210-4bf8-8dad-cf87c73b1467">
													<gml:posList>35.25956017477023 139.73806335690034 19.4009 35.25958757311341 139.7379536862642 19.4009 35.2595552208113 139.738056900443 19.4009 35.25956017477023 139.73806335690034 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d06fa25a-c891-4340-8be7-1e26eefb0b34">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d4374676-f264-4445-afa9-f242d4ca8e62">
													<gml:posList>35.259563885996236 139.7380713974059 19.4009 35.259652440862574 139.73802299166348 19.4009 35.25956017477023 139.73806335690034 19.4009 35.259563885996236 139.7380713974059 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e3501f41-c327-4226-8f3c-42f10c3fda07">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d869e84f-fdb7-4915-849d-b3c8b8e46bff">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.259563885996236 139.7380713974059 19.4009 35.25956645200297 139.7380789337016 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6ddab183-a241-4299-bc0b-ffb459d92a67">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c67cf878-5246-48ad-947c-df2dfd15a90c">
													<gml:posList>35.25956819784299 139.73808664680107 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25956645200297 139.7380789337016 19.4009 35.25956819784299 139.73808664680107 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e846f43e-1701-425d-a687-fa036abd2ad4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c31ef334-4b05-40e7-ab6b-d7dde5857dca">
													<gml:posList>35.25956951320005 139.73809716291348 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25956819784299 139.73808664680107 19.4009 35.25956951320005 139.73809716291348 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e9b12228-a7ae-48d6-9628-d20b35d788b8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_614380d1-6f26-451d-9ade-9ff88cfe9e6a">
													<gml:posList>35.259569683415414 139.7381072737272 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25956951320005 139.73809716291348 19.4009 35.259569683415414 139.7381072737272 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_071e6ad9-1ed1-4be0-9b96-b9bcd063309d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f5a9c2a9-072e-4afa-a6b9-7fdf2119e35d">
													<gml:posList>35.25956967443283 139.7381187695197 19.4009 35.25964103195404 139.7380843635364 19.4009 35.259569683415414 139.7381072737272 19.4009 35.25956967443283 139.7381187695197 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7943dca9-b41a-4735-86be-fe4902e262c2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_205420b7-8791-4cfb-aef9-a2b9a03b68f2">
													<gml:posList>35.2595761636311 139.73814024783388 19.4009 35.25956967443283 139.7381187695197 19.4009 35.25957148518652 139.73812879049305 19.4009 35.2595761636311 139.73814024783388 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_682de888-9646-479b-92cc-548de074fca1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_943afc81-9051-4a34-84bf-5be1b0a6b4e9">
													<gml:posList>35.2595761636311 139.73814024783388 19.4009 35.25957148518652 139.73812879049305 19.4009 35.2595731750611 139.7381341187792 19.4009 35.2595761636311 139.73814024783388 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3ba97743-0ff2-4e4a-a611-fc23bfe1cdc2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cc4cd06b-bded-4c08-a5da-5592a85a8db7">
													<gml:posList>35.2595761636311 139.73814024783388 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25956967443283 139.7381187695197 19.4009 35.2595761636311 139.73814024783388 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cbb6d27c-1d49-4cc7-8732-1776fd45fe3d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_82b5be4a-2bc3-40a4-9ce0-7711c4e4feae">
													<gml:posList>35.25958135314272 139.73814820968445 19.4009 35.25964103195404 139.7380843635364 19.4009 35.2595761636311 139.73814024783388 19.4009 35.25958135314272 139.73814820968445 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_55263213-32bf-4f43-aeeb-a608c80bca5e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dfa37f70-2436-4652-9b86-11cca47bb362">
													<gml:posList>35.25958622269745 139.73815378503826 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25958135314272 139.73814820968445 19.4009 35.25958622269745 139.73815378503826 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b0cb929a-e226-414c-8bd0-9189277c5281">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c27547a6-e961-437e-8f16-55be188f5c20">
													<gml:posList>35.25954861784281 139.73805122622278 19.4009 35.25958757311341 139.7379536862642 19.4009 35.259580504322734 139.73795172729461 19.4009 35.25954861784281 139.73805122622278 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_202e9272-8c2d-422c-b08c-5a4030401652">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c1715fa3-55e4-4673-82bd-fd9c0ccf4f67">
													<gml:posList>35.259590402061896 139.73815770537246 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25958622269745 139.73815378503826 19.4009 35.259590402061896 139.73815770537246 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3e931338-a4ce-4059-80af-30686ac14002">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f0164073-df39-4581-934f-838af4c7d728">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.25965338261245 139.73802839776027 19.4009 35.259563885996236 139.7380713974059 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ad7f3038-b8b3-43fe-80c4-6bad6210787d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7058d999-3937-4e6b-8473-eb02c6b3e12e">
													<gml:posList>35.259669844540305 139.73811392890445 19.4009 35.259673147992196 139.73810463593276 19.4009 35.25964103195404 139.7380843635364 19.4009 35.259669844540305 139.73811392890445 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3db6a45d-616d-4825-8a5d-186837007e2d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9477027e-0dbf-44ea-8b4a-80eb57364434">
													<gml:posList>35.259669844540305 139.73811392890445 19.4009 35.259671872505635 139.73811041829376 19.4009 35.259673147992196 139.73810463593276 19.4009 35.259669844540305 139.73811392890445 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_475b9e50-066b-490b-8bdf-3e97437a2978">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d43067ea-0503-4de4-a018-a37033a76254">
													<gml:posList>35.259673147992196 139.73810463593276 19.4009 35.25967385533306 139.73809854650938 19.4009 35.25964103195404 139.7380843635364 19.4009 35.259673147992196 139.73810463593276 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_86f44210-2dee-4b01-b228-cd1868015218">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a8646e01-a538-4722-8ce1-0150eae8957a">
													<gml:posList>35.25967385533306 139.73809854650938 19.4009 35.25967406679861 139.73809234776354 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25967385533306 139.73809854650938 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e7e64e1d-5f98-47e5-9318-922c4a21fe5a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_974057dd-d2de-4678-aaa2-4b0438feb5d7">
													<gml:posList>35.25967406679861 139.73809234776354 19.4009 35.25967249080396 139.73808282106472 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25967406679861 139.73809234776354 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2e36affd-9935-43e4-9275-426e56f914e7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c3de8e28-8511-4fe5-af47-ea9cee6fcaf7">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.25967249080396 139.73808282106472 19.4009 35.25967066445761 139.7380758993473 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_26237b7f-c51f-4268-abd1-20c13f0f7c3f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_72965f9b-abb7-4b14-83cc-322cde82fb57">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.25967066445761 139.7380758993473 19.4009 35.2596575322844 139.73804374627193 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bdc2961a-b507-48f7-96f9-1e445f10e744">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7d6331c5-b654-4933-9a04-388e03fd62a4">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.2596575322844 139.73804374627193 19.4009 35.25965537224956 139.7380366271229 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8c2ad967-d5c5-414c-a2a1-957eaa3f7ca1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ab93d5a8-67d4-451a-9965-cbc81f83f9b5">
													<gml:posList>35.25964103195404 139.7380843635364 19.4009 35.25965537224956 139.7380366271229 19.4009 35.25965338261245 139.73802839776027 19.4009 35.25964103195404 139.7380843635364 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_aceb5564-ec92-4daf-a466-3b6153665ad9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_43fa84da-601a-48a0-999c-35c9a628d009">
													<gml:posList>35.259563885996236 139.7380713974059 19.4009 35.25965338261245 139.73802839776027 19.4009 35.259652440862574 139.73802299166348 19.4009 35.259563885996236 139.7380713974059 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c0f3c1dc-9604-401e-a1fb-c9b6d054b8f8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3f1c09df-fe63-4640-8b79-73a191de9678">
													<gml:posList>35.25956017477023 139.73806335690034 19.4009 35.259652440862574 139.73802299166348 19.4009 35.25965208378042 139.73801598030684 19.4009 35.25956017477023 139.73806335690034 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_843f4803-5374-4718-9967-21a7a532292f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_966ba344-cf47-4dfe-90b7-df39bb5fa89b">
													<gml:posList>35.25956017477023 139.73806335690034 19.4009 35.25965208378042 139.73801598030684 19.4009 35.25959506323896 139.7379526773771 19.4009 35.25956017477023 139.73806335690034 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b094c05a-8a1c-4c5b-b8f3-31c2e88fb286">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cc1e17ee-9928-4061-b51a-77c62df7d5c9">
													<gml:posList>35.25965208378042 139.73801598030684 19.4009 35.259652466124535 139.73800928680149 19.4009 35.25959506323896 139.7379526773771 19.4009 35.25965208378042 139.73801598030684 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_34b2f039-c56e-4281-a2cc-4dbd55d9e9ed">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e2fd7824-99f0-4772-be55-d25c4c967452">
													<gml:posList>35.25965316428178 139.73800298857495 19.4009 35.25965435017399 139.73799790969406 19.4009 35.25960347874844 139.73794774389137 19.4009 35.25965316428178 139.73800298857495 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c250d256-d22a-461b-8c36-c66d6e562e9c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ac3c5fe9-55d5-47bb-b965-70928c6fd7de">
													<gml:posList>35.25965435017399 139.73799790969406 19.4009 35.25965619403464 139.73799273113025 19.4009 35.25960347874844 139.73794774389137 19.4009 35.25965435017399 139.73799790969406 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e1376a1f-3392-4612-8875-1c2f72e93ff3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2831272f-6c30-4275-9b5a-4d1697bda214">
													<gml:posList>35.259658939727075 139.73798805706116 19.4009 35.259662676381495 139.73798260152373 19.4009 35.259609584950034 139.73794073595585 19.4009 35.259658939727075 139.73798805706116 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c9f113f4-7662-4737-b159-1f0f67c356b9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_78d8b4a4-e965-4bc2-a396-74eb74ddf506">
													<gml:posList>35.259662676381495 139.73798260152373 19.4009 35.25966688303696 139.73797873902072 19.4009 35.25961261674252 139.7379330722079 19.4009 35.259662676381495 139.73798260152373 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5e684cec-6be9-479e-b2ae-0f9a364f52fe">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_054c0f21-1cc2-4151-a89e-704b3ecd3973">
													<gml:posList>35.25966688303696 139.73797873902072 19.4009 35.25967126129378 139.7379752939456 19.4009 35.25961261674252 139.7379330722079 19.4009 35.25966688303696 139.73797873902072 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c1d5e79b-71c6-4a93-b1a8-a7225c16eef3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_48957d6f-88eb-4abd-aa69-ae03564a901c">
													<gml:posList>35.25967126129378 139.7379752939456 19.4009 35.25967792936525 139.7379720659927 19.4009 35.25961357483846 139.73792490533882 19.4009 35.25967126129378 139.7379752939456 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9ba8b490-d939-4a42-965a-6b86eb362058">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0e05f9ca-8bd2-447b-82a0-5d2770d545ed">
													<gml:posList>35.25967792936525 139.7379720659927 19.4009 35.25968359802319 139.7379703338836 19.4009 35.25970579949657 139.7379006406829 19.4009 35.25967792936525 139.7379720659927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_46102466-e7d1-4f68-be2f-6924d2f5fb81">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aa285fbf-53e4-4810-9e12-af4581f99a9a">
													<gml:posList>35.25968359802319 139.7379703338836 19.4009 35.25968885319091 139.737970085942 19.4009 35.25970937292682 139.73790539527212 19.4009 35.25968359802319 139.7379703338836 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_30367556-f616-4e35-af32-efc3a4114a67">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7a63101f-1439-4902-aeb5-6a9d47fa3441">
													<gml:posList>35.25969377546042 139.73797064067853 19.4009 35.25971373011884 139.73790953348902 19.4009 35.25968885319091 139.737970085942 19.4009 35.25969377546042 139.73797064067853 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5a426efb-edeb-46ab-a482-4aec275e6c38">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0f0fb8e8-1e21-445d-b915-3a9f15482ca0">
													<gml:posList>35.259699744354364 139.73797241410668 19.4009 35.2597173468958 139.73791210096826 19.4009 35.25969377546042 139.73797064067853 19.4009 35.259699744354364 139.73797241410668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ed984960-c2e7-4f66-aa36-c1fc5145b5f7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9f039b21-9bd1-4815-ac50-d478a9f5a182">
													<gml:posList>35.25970529952417 139.73797537496668 19.4009 35.2597173468958 139.73791210096826 19.4009 35.259699744354364 139.73797241410668 19.4009 35.25970529952417 139.73797537496668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b32acc10-2ab6-4c41-9969-354944922cd9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_24596d6d-2b20-4aee-a989-3e1adf4fa6b9">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.25978517302655 139.73790346005242 19.4009 35.25973399693007 139.73791278482804 19.4009 35.25970529952417 139.73797537496668 19.4009 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_68e25f95-8d68-4dd6-9b72-0d4ec421e7ba">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a0ac9ad4-31eb-4cc9-97b7-5f410c01bfef">
													<gml:posList>35.25978477852568 139.73803198061987 19.4009 35.259824461949364 139.73802342769727 19.4009 35.25977880916527 139.73802961371203 19.4009 35.25978477852568 139.73803198061987 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_746db594-061e-4e8e-9168-5b6fe69dd271">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_21b5509c-a504-4aff-9c55-c81efe7364fc">
													<gml:posList>35.259790675061595 139.73803344641183 19.4009 35.259824461949364 139.73802342769727 19.4009 35.25978477852568 139.73803198061987 19.4009 35.259790675061595 139.73803344641183 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_28c6dceb-0659-4b48-8e8c-1cf83bfd75f2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_08331aed-b11b-4253-a74a-0898e4ffd225">
													<gml:posList>35.25979755354563 139.73803413074594 19.4009 35.259824461949364 139.73802342769727 19.4009 35.259790675061595 139.73803344641183 19.4009 35.25979755354563 139.73803413074594 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7cd0b312-0bff-46ef-a2f8-0d521f6381ec">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f460975b-481a-45f6-9153-697b44ede779">
													<gml:posList>35.25979755354563 139.73803413074594 19.4009 35.25980395362932 139.7380340023607 19.4009 35.259814731728945 139.7380301211701 19.4009 35.25979755354563 139.73803413074594 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2b788517-b565-43ea-add0-bac167f37ef3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6c462bef-13b2-4fb9-a43f-55217055a031">
													<gml:posList>35.25965316428178 139.73800298857495 19.4009 35.25960347874844 139.73794774389137 19.4009 35.25959506323896 139.7379526773771 19.4009 35.25965316428178 139.73800298857495 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_db6a338d-1205-4a9b-bfa6-850865af1b5d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8795a265-6b02-4dcb-bcfa-40a21ad7e3a4">
													<gml:posList>35.25980395362932 139.7380340023607 19.4009 35.25980921702374 139.73803275429924 19.4009 35.259814731728945 139.7380301211701 19.4009 35.25980395362932 139.7380340023607 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_39e657ca-c93e-445a-8a83-127692f0b937">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_355d3845-cea8-4b8a-b885-b7a1e7414350">
													<gml:posList>35.25979755354563 139.73803413074594 19.4009 35.259814731728945 139.7380301211701 19.4009 35.259824461949364 139.73802342769727 19.4009 35.25979755354563 139.73803413074594 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8dc4a85e-b642-47ec-b887-cbb252ab0efc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_390d6165-ca8d-417a-8cf1-6acccb838ddf">
													<gml:posList>35.25965619403464 139.73799273113025 19.4009 35.259609584950034 139.73794073595585 19.4009 35.25960347874844 139.73794774389137 19.4009 35.25965619403464 139.73799273113025 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b8de2146-cc1f-4242-a333-7c468b7b8cc9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2f88afa8-7e61-41e8-95b0-10237a2c9720">
													<gml:posList>35.259814731728945 139.7380301211701 19.4009 35.25981959722873 139.73802726899535 19.4009 35.259824461949364 139.73802342769727 19.4009 35.259814731728945 139.7380301211701 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c0d45276-362d-4111-b84f-0c129fceedcd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_58054184-7ab9-47c8-9049-d9175ab500c7">
													<gml:posList>35.2595552208113 139.738056900443 19.4009 35.25958757311341 139.7379536862642 19.4009 35.25954861784281 139.73805122622278 19.4009 35.2595552208113 139.738056900443 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a9e5774f-6092-4030-8950-a843064cf725">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b8ca5a88-966a-4140-a546-9a1aeef91ff6">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.259824461949364 139.73802342769727 19.4009 35.259837124730936 139.73800897166032 19.4009 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_42b78613-a14a-4c1a-9114-12264cbd0e08">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_39e6fb32-a104-4e04-8a09-3eb0c1dec9d6">
													<gml:posList>35.259662676381495 139.73798260152373 19.4009 35.25961261674252 139.7379330722079 19.4009 35.259609584950034 139.73794073595585 19.4009 35.259662676381495 139.73798260152373 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ea4055bd-9269-408a-a8a7-e79666c7e5f6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c53dca4d-64e8-4ab3-a56d-fffd7fde2dfe">
													<gml:posList>35.259824461949364 139.73802342769727 19.4009 35.259829830607025 139.738018486782 19.4009 35.259837124730936 139.73800897166032 19.4009 35.259824461949364 139.73802342769727 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4aecc92c-e935-458d-9f79-4a86a3321295">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3b0d432b-2493-48f6-8436-894d9aa6902d">
													<gml:posList>35.25954861784281 139.73805122622278 19.4009 35.259580504322734 139.73795172729461 19.4009 35.25954233187303 139.73804745294183 19.4009 35.25954861784281 139.73805122622278 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_10eebf4a-b6af-40b7-be96-f2469f59f82e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f34e6096-56db-4ce4-adec-ca6db3410e4e">
													<gml:posList>35.259829830607025 139.738018486782 19.4009 35.25983322612906 139.73801482304748 19.4009 35.259837124730936 139.73800897166032 19.4009 35.259829830607025 139.738018486782 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2de98bdd-38ca-4e29-9939-d312d8610781">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_78fd76c2-2630-4b03-8264-2c02ba61cd79">
													<gml:posList>35.25967126129378 139.7379752939456 19.4009 35.25961357483846 139.73792490533882 19.4009 35.25961261674252 139.7379330722079 19.4009 35.25967126129378 139.7379752939456 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_46df70ac-796d-4877-b824-c99d0aff6d0d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b7722c75-e80a-4dd4-8667-9ba7cb3f4b74">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.259837124730936 139.73800897166032 19.4009 35.25982030831789 139.73791156265102 19.4009 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_259a549e-f13e-4d25-807b-c030ceac8589">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ac52a997-12af-4e81-b11b-c56484f761d2">
													<gml:posList>35.25954233187303 139.73804745294183 19.4009 35.25956587536673 139.73794197411962 19.4009 35.259536029215894 139.73804538316614 19.4009 35.25954233187303 139.73804745294183 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c938b678-250d-419d-812b-d9c53980c7f8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_843bf57e-f1f8-42ec-8d69-17cdc2434617">
													<gml:posList>35.259837124730936 139.73800897166032 19.4009 35.25984094211692 139.738003010465 19.4009 35.259838866050906 139.7379308727791 19.4009 35.259837124730936 139.73800897166032 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_449060fa-89a0-4f16-b260-9f6ada513074">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5f124ecc-641b-4f25-8ee0-eb60ae8ff94f">
													<gml:posList>35.25961357483846 139.73792490533882 19.4009 35.25970250365558 139.73789353385533 19.4009 35.25961311779565 139.73791688300133 19.4009 35.25961357483846 139.73792490533882 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f9008067-82a7-4ff4-b81f-3ab8f691ea18">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a675f304-0162-4fa6-afc2-a8d3ad972391">
													<gml:posList>35.25984094211692 139.738003010465 19.4009 35.25984435330329 139.7379963463677 19.4009 35.25984865931544 139.7379812956465 19.4009 35.25984094211692 139.738003010465 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e112c815-f165-4cb7-8d08-8aab199b676e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_599e562d-75b5-4355-8a91-3f672a5c273b">
													<gml:posList>35.25984435330329 139.7379963463677 19.4009 35.2598467011007 139.73799006817467 19.4009 35.25984865931544 139.7379812956465 19.4009 35.25984435330329 139.7379963463677 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bb41fe6f-0746-427c-9f71-ffe997d6c72d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_632a31bf-6e81-4ce2-98ac-553f88abc06c">
													<gml:posList>35.25961311779565 139.73791688300133 19.4009 35.25970101883761 139.7378853368703 19.4009 35.25961162558559 139.73791074120786 19.4009 35.25961311779565 139.73791688300133 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_82064556-a380-4720-9b4c-0f411b5e8c30">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dc2d6332-f3b6-4f9e-90e6-9ec799501dec">
													<gml:posList>35.25984094211692 139.738003010465 19.4009 35.25984865931544 139.7379812956465 19.4009 35.259838866050906 139.7379308727791 19.4009 35.25984094211692 139.738003010465 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fb08a902-752c-4729-b771-1629cddb5c99">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3a433d40-932f-4361-9bfa-b40275e1c487">
													<gml:posList>35.259652466124535 139.73800928680149 19.4009 35.25965316428178 139.73800298857495 19.4009 35.25959506323896 139.7379526773771 19.4009 35.259652466124535 139.73800928680149 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d8a617e5-501b-40b5-992f-bb7e127b8313">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_af0f87eb-e509-41d5-b536-be147229e336">
													<gml:posList>35.25984865931544 139.7379812956465 19.4009 35.259850023986424 139.73797430423687 19.4009 35.25984999934051 139.73796590770004 19.4009 35.25984865931544 139.7379812956465 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1bd4de66-31e6-43aa-beb8-8775bb57203b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ae0d8417-f74f-4389-8530-a71fe95189f3">
													<gml:posList>35.25961162558559 139.73791074120786 19.4009 35.25970045201622 139.73787528145706 19.4009 35.259607562148425 139.73790188784028 19.4009 35.25961162558559 139.73791074120786 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2d2542a4-5ec1-4c84-bca8-7011b0326c32">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c02742fb-0a5a-474a-b641-65d1425396bc">
													<gml:posList>35.25984865931544 139.7379812956465 19.4009 35.25984999934051 139.73796590770004 19.4009 35.25984210640868 139.73793621025192 19.4009 35.25984865931544 139.7379812956465 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_513dcb16-471d-47e0-94b1-32e5dbe66408">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6f974768-cb91-4f1e-beed-c723623fec80">
													<gml:posList>35.25965619403464 139.73799273113025 19.4009 35.259658939727075 139.73798805706116 19.4009 35.259609584950034 139.73794073595585 19.4009 35.25965619403464 139.73799273113025 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8f629602-c96a-48cb-9f0e-298872750b97">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d5869246-3805-4b0a-89e4-6b4e8530df8f">
													<gml:posList>35.25984999934051 139.73796590770004 19.4009 35.25984948869948 139.7379585008569 19.4009 35.259848384125355 139.7379523805712 19.4009 35.25984999934051 139.73796590770004 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d96d64ae-f0f4-4d09-b092-27427622b238">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dd25a4f1-01e6-4184-b549-b17e157c086b">
													<gml:posList>35.259607562148425 139.73790188784028 19.4009 35.25970358105886 139.7378195132624 19.4009 35.25957140349773 139.73784207742708 19.4009 35.259607562148425 139.73790188784028 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5e48cbc4-d74f-4f43-8f8d-2c65f1ded15d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2c08e554-5573-4c48-99ec-d82b1800f9e1">
													<gml:posList>35.25984999934051 139.73796590770004 19.4009 35.259848384125355 139.7379523805712 19.4009 35.25984210640868 139.73793621025192 19.4009 35.25984999934051 139.73796590770004 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fa9afec1-15a2-49ee-8393-5bf3103a6756">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_744e2863-f1f3-48ac-9fcf-48d567c0fd45">
													<gml:posList>35.259848384125355 139.7379523805712 19.4009 35.259846702555414 139.73794616204933 19.4009 35.25984429113582 139.73794034003262 19.4009 35.259848384125355 139.7379523805712 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a82b0ea2-9d6f-4666-91e6-37c19b67d34d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_45d10e3a-6c6e-4dfc-9ff9-07e5d5470321">
													<gml:posList>35.25957140349773 139.73784207742708 19.4009 35.259681398031 139.73775263066943 19.4009 35.25956863825879 139.7378333983881 19.4009 35.25957140349773 139.73784207742708 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_59a9a5e8-0a01-4909-9957-e34b5b74d63d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d9d5d87d-6bb6-4e06-b25a-f7e850833e61">
													<gml:posList>35.259848384125355 139.7379523805712 19.4009 35.25984429113582 139.73794034003262 19.4009 35.25984210640868 139.73793621025192 19.4009 35.259848384125355 139.7379523805712 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d219a082-31d4-42a0-a9e7-0e00c3903e2a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9a22994c-aebf-4ab8-a59f-52be79fdb85d">
													<gml:posList>35.25984865931544 139.7379812956465 19.4009 35.25984210640868 139.73793621025192 19.4009 35.259838866050906 139.7379308727791 19.4009 35.25984865931544 139.7379812956465 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c4542e81-2bfb-468f-9cc4-2802dcd2c1fc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_831849ed-3ec7-44e3-945f-bc7c5f73a3c3">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.259565011686625 139.73781842295804 19.4009 35.25956674088509 139.73782787252776 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ae1d7eca-1e19-443d-a58d-442f7f947cab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ef97a9b7-7628-41d8-9efa-1023b937d18e">
													<gml:posList>35.259837124730936 139.73800897166032 19.4009 35.259838866050906 139.7379308727791 19.4009 35.25982030831789 139.73791156265102 19.4009 35.259837124730936 139.73800897166032 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_373d4d21-c55a-49b7-bc45-5445fcda40d8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_34f80e6d-2d4b-4c5d-b85b-572d62d0c2b7">
													<gml:posList>35.259838866050906 139.7379308727791 19.4009 35.25983513867611 139.73792522814998 19.4009 35.25982030831789 139.73791156265102 19.4009 35.259838866050906 139.7379308727791 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3ad8a279-90a4-4c29-a20d-02d90c85c822">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_de4434c1-3e34-4306-98a4-0fc962b9e3bd">
													<gml:posList>35.25983513867611 139.73792522814998 19.4009 35.25983115028391 139.73792008937957 19.4009 35.25982691936237 139.7379160389303 19.4009 35.25983513867611 139.73792522814998 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7bbf306d-c689-476d-9d10-dd0e1f8a7e5a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6f5c7fc4-87ab-44ba-a654-8bfe43c16818">
													<gml:posList>35.25983513867611 139.73792522814998 19.4009 35.25982691936237 139.7379160389303 19.4009 35.25982030831789 139.73791156265102 19.4009 35.25983513867611 139.73792522814998 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e47dcd49-119b-4424-9c50-17482c677ffa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_da6c5ebd-2596-495c-8c30-1cce4413ea04">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.25982030831789 139.73791156265102 19.4009 35.25981377002061 139.73790788857642 19.4009 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f2cc9c48-0756-4d8c-bb15-143db142e3e7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_018fe2fb-b126-41a3-8218-c4935055d69b">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.25981377002061 139.73790788857642 19.4009 35.25978517302655 139.73790346005242 19.4009 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f5f2118e-7c9f-4bcc-801d-dbc408fdbe62">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f36c683f-0e95-43d6-9812-9668f27a96be">
													<gml:posList>35.25981377002061 139.73790788857642 19.4009 35.25980821523928 139.73790542227852 19.4009 35.25978517302655 139.73790346005242 19.4009 35.25981377002061 139.73790788857642 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_afd6d007-607c-49a0-bf19-d24680c10028">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_68295c10-aee3-4925-a52b-526aff08fadb">
													<gml:posList>35.25980821523928 139.73790542227852 19.4009 35.259803301117174 139.73790376850937 19.4009 35.25979732391873 139.73790289629525 19.4009 35.25980821523928 139.73790542227852 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_71cf1525-4316-4610-ac03-a9347ed32a54">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9f9a5553-9b80-4376-bedc-ab44bad8e684">
													<gml:posList>35.25980821523928 139.73790542227852 19.4009 35.25979732391873 139.73790289629525 19.4009 35.25979150052736 139.7379027382679 19.4009 35.25980821523928 139.73790542227852 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_71cf663e-a6fd-4b20-b822-851c20adc7f2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8f396708-0dc6-4f5b-8f86-5bb7acfd8b30">
													<gml:posList>35.25980821523928 139.73790542227852 19.4009 35.25979150052736 139.7379027382679 19.4009 35.25978517302655 139.73790346005242 19.4009 35.25980821523928 139.73790542227852 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d1101f78-ce30-4311-bea8-b2d0bc680cab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_45139b6f-72b5-4c8a-8803-147deb37fcf8">
													<gml:posList>35.25970529952417 139.73797537496668 19.4009 35.25973399693007 139.73791278482804 19.4009 35.25972734499969 139.73791361689402 19.4009 35.25970529952417 139.73797537496668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c932e035-bfc5-4f63-91a8-147e30ab3b6c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_51cc66a9-9642-466c-a9c4-bc3d4bf8e63a">
													<gml:posList>35.25970529952417 139.73797537496668 19.4009 35.2597223418349 139.7379133589924 19.4009 35.2597173468958 139.73791210096826 19.4009 35.25970529952417 139.73797537496668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_61dd4625-6e45-4147-ae46-8077765acf83">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aec7a061-49df-455a-9987-62140cd909fa">
													<gml:posList>35.25970529952417 139.73797537496668 19.4009 35.25972734499969 139.73791361689402 19.4009 35.2597223418349 139.7379133589924 19.4009 35.25970529952417 139.73797537496668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d69631f0-4e71-4ff1-a550-cc3ecb457517">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2c1cb899-a870-4cab-bd9a-1cc973c62209">
													<gml:posList>35.25961311779565 139.73791688300133 19.4009 35.25970250365558 139.73789353385533 19.4009 35.25970101883761 139.7378853368703 19.4009 35.25961311779565 139.73791688300133 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_168996ad-e28d-4f10-bc58-05f5f356251c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_492ef596-7d56-43ea-9484-7d3b382b8a5a">
													<gml:posList>35.25969377546042 139.73797064067853 19.4009 35.2597173468958 139.73791210096826 19.4009 35.25971373011884 139.73790953348902 19.4009 35.25969377546042 139.73797064067853 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9a8a47ee-e492-462e-b8f2-797cb8c48412">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5151b679-6c99-4a2d-afdb-69c68ef4d0f2">
													<gml:posList>35.25968885319091 139.737970085942 19.4009 35.25971373011884 139.73790953348902 19.4009 35.25970937292682 139.73790539527212 19.4009 35.25968885319091 139.737970085942 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_29673659-7f5b-49a7-a8bb-f26f46a5b0e2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f46f68df-941f-4d4f-b302-365bbed0e037">
													<gml:posList>35.25968359802319 139.7379703338836 19.4009 35.25970937292682 139.73790539527212 19.4009 35.25970579949657 139.7379006406829 19.4009 35.25968359802319 139.7379703338836 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ded6b680-2039-4166-9aeb-d8848796bca4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b94dfe52-2985-4568-a0dc-20d970dc29d4">
													<gml:posList>35.25967792936525 139.7379720659927 19.4009 35.25970579949657 139.7379006406829 19.4009 35.25970250365558 139.73789353385533 19.4009 35.25967792936525 139.7379720659927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_73bbce7d-3bb6-4959-baf4-760916fdbbdc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b75b0b02-495c-4107-9ed7-dc088ef30c83">
													<gml:posList>35.25967792936525 139.7379720659927 19.4009 35.25970250365558 139.73789353385533 19.4009 35.25961357483846 139.73792490533882 19.4009 35.25967792936525 139.7379720659927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_65427c19-c7f4-4f5e-8c3a-4e59bc2ddab1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d1cd7a7a-da11-4630-bce9-d1d95b6f9e31">
													<gml:posList>35.25961162558559 139.73791074120786 19.4009 35.25970101883761 139.7378853368703 19.4009 35.25970045201622 139.73787528145706 19.4009 35.25961162558559 139.73791074120786 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9d5546c4-d8af-4325-91d9-27c3a4b53357">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fcfc9ce1-7b6e-41e6-977a-3545d0f48d98">
													<gml:posList>35.259607562148425 139.73790188784028 19.4009 35.25970045201622 139.73787528145706 19.4009 35.25970358105886 139.7378195132624 19.4009 35.259607562148425 139.73790188784028 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5ef5ea81-87c1-428e-ac7f-b70b41da2251">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_760f586c-9d38-4d1b-aaef-5dee8348ec92">
													<gml:posList>35.25970358105886 139.7378195132624 19.4009 35.25970329143802 139.73780662203973 19.4009 35.25969742999061 139.7377810985704 19.4009 35.25970358105886 139.7378195132624 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_63acea96-0d8e-4ae3-b8ce-09d879b57f29">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_64dd348d-0b8c-4587-a0c0-084d62e85d65">
													<gml:posList>35.25970329143802 139.73780662203973 19.4009 35.259702582237566 139.73779891870717 19.4009 35.259700330326815 139.73778962359927 19.4009 35.25970329143802 139.73780662203973 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2e33f722-8c3d-4852-952b-24d3200a7c0c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_be1bfc6b-ca11-4743-ba50-471eaf92bf0d">
													<gml:posList>35.25970329143802 139.73780662203973 19.4009 35.259700330326815 139.73778962359927 19.4009 35.25969742999061 139.7377810985704 19.4009 35.25970329143802 139.73780662203973 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ca7b52e1-3a05-4a35-9425-2af181a6ac1c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e57e1b3d-56a6-46ec-9c8a-1387a36839aa">
													<gml:posList>35.25957140349773 139.73784207742708 19.4009 35.25970358105886 139.7378195132624 19.4009 35.25969742999061 139.7377810985704 19.4009 35.25957140349773 139.73784207742708 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4a221a79-90b1-4c04-b1f9-1dc172f5199f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_13919d43-aacb-4443-8edc-077c11650b54">
													<gml:posList>35.25969742999061 139.7377810985704 19.4009 35.2596947741605 139.7377739909971 19.4009 35.25968777805937 139.7377613494349 19.4009 35.25969742999061 139.7377810985704 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5962f7e7-8be6-40f9-9920-ed410b100705">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c02bca56-4cad-4330-865a-b31d2fd44bc2">
													<gml:posList>35.25957140349773 139.73784207742708 19.4009 35.25969742999061 139.7377810985704 19.4009 35.25968777805937 139.7377613494349 19.4009 35.25957140349773 139.73784207742708 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d2b650f1-03a7-4a7c-9b67-519005ca30b6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c4bd030a-d1a0-4870-9012-8b4e6d0c57af">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.25956475477397 139.73780128948985 19.4009 35.259565011686625 139.73781842295804 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7f152770-377a-47f0-86b4-bc67dea52d3c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_07c80ed5-7635-4aff-ba93-e82b1c82a284">
													<gml:posList>35.25957140349773 139.73784207742708 19.4009 35.25968777805937 139.7377613494349 19.4009 35.259681398031 139.73775263066943 19.4009 35.25957140349773 139.73784207742708 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cc68d6e5-f840-41f2-9cf2-cbc018558c59">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_51a9c5c4-611b-46b6-bf75-ba82017d79f7">
													<gml:posList>35.25953044928078 139.7380453127659 19.4009 35.25956587536673 139.73794197411962 19.4009 35.25954306425423 139.7379244274751 19.4009 35.25953044928078 139.7380453127659 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8e752e9f-9a3f-4a84-b376-4dde8cc9f75b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ea8faed2-d518-408e-9511-42f11ddf9a28">
													<gml:posList>35.259681398031 139.73775263066943 19.4009 35.259673610879936 139.7377427925526 19.4009 35.25965540144442 139.73773080159927 19.4009 35.259681398031 139.73775263066943 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_348b8e81-baf9-4b71-9cdb-921caf2494cd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6c22e3bb-ee60-4a87-8585-94ad37b7c741">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.259579546768606 139.7377549373104 19.4009 35.25956475477397 139.73780128948985 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0219ef56-7ab1-4443-95fe-c12dde68e9f9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2d96d206-0a3a-449e-8a7c-e27f6fb35998">
													<gml:posList>35.259673610879936 139.7377427925526 19.4009 35.259666051699966 139.73773626223345 19.4009 35.25965540144442 139.73773080159927 19.4009 35.259673610879936 139.7377427925526 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9df0a603-27ae-4d79-9493-425c4528cfd5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e7954417-d761-4daf-a053-5963efadae28">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.259681398031 139.73775263066943 19.4009 35.25965540144442 139.73773080159927 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bed73f19-96c2-43f2-8a4d-930898fcf9ab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_12281d61-5ca7-4fc3-aab2-eb8478689971">
													<gml:posList>35.25956475477397 139.73780128948985 19.4009 35.25957327228259 139.7377657151043 19.4009 35.259565888566 139.73778731957597 19.4009 35.25956475477397 139.73780128948985 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cc3db313-7116-48a7-83fd-d89a193809e8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_06ac259e-f30d-4af6-9a63-11f07a02866b">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.25965540144442 139.73773080159927 19.4009 35.2596427960501 139.7377265741697 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7636a09d-6896-476d-b9e4-867785ea1c67">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1eef10b0-61e0-4eae-b9d5-0428d2509ab5">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.25945047141383 139.73788189395822 19.4009 35.259453151376654 139.73788531976322 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_287cba2e-f017-467d-bfce-b4d6783184df">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9637b611-ea50-4d15-88cd-84a9f9d70fe3">
													<gml:posList>35.259604344979664 139.73773179572896 19.4009 35.2596427960501 139.7377265741697 19.4009 35.25963146367433 139.73772487300138 19.4009 35.259604344979664 139.73773179572896 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8a7ec0c6-61f3-47c6-88ab-14ff26a853f3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f984dce3-644a-4e1a-b600-a80a23cf590d">
													<gml:posList>35.259565888566 139.73778731957597 19.4009 35.25957327228259 139.7377657151043 19.4009 35.259568287349126 139.7377771288163 19.4009 35.259565888566 139.73778731957597 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_740e4c05-194b-433f-b1a1-51517857df16">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6c3d3a20-e38b-457c-b80d-20d07aaac56c">
													<gml:posList>35.259604344979664 139.73773179572896 19.4009 35.25963146367433 139.73772487300138 19.4009 35.25962115129924 139.7377249180835 19.4009 35.259604344979664 139.73773179572896 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ac2863a8-c1c6-4135-bb43-61a508cb1fba">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a197eb7e-b4b7-4455-b397-b2be48728e52">
													<gml:posList>35.259604344979664 139.73773179572896 19.4009 35.25962115129924 139.7377249180835 19.4009 35.259612364222654 139.7377273352654 19.4009 35.259604344979664 139.73773179572896 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_afdf0983-effd-4217-a515-bfd7b634e039">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aa6dfeca-90df-49c0-ba77-039a6edee28c">
													<gml:posList>35.25959474983381 139.73773829123564 19.4009 35.2596427960501 139.7377265741697 19.4009 35.259604344979664 139.73773179572896 19.4009 35.25959474983381 139.73773829123564 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_de0afc3d-663c-4ba0-b0d3-f7982559706a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e6960080-546c-4f9d-a9c6-f82fb27bf12b">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.2596427960501 139.7377265741697 19.4009 35.25959474983381 139.73773829123564 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0f890eff-baab-4acc-a76b-b8dcb7369742">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5e420024-c8c5-46b4-8606-61380d77d2f3">
													<gml:posList>35.259579546768606 139.7377549373104 19.4009 35.25959474983381 139.73773829123564 19.4009 35.25958721923983 139.73774512501384 19.4009 35.259579546768606 139.7377549373104 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_30181e8f-3d0c-4a6d-8747-32021bbb08b1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_efd7a0fd-0736-4e36-9d48-a4b7bd705756">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.25959474983381 139.73773829123564 19.4009 35.259579546768606 139.7377549373104 19.4009 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6248c42e-d736-4b3f-afb7-ae274a4e1e4c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7e87e43f-5c25-4008-aa07-988fd7157b49">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.2594409612081 139.73787037637467 19.4009 35.25945047141383 139.73788189395822 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_355b2329-195f-43a1-a08e-d095c00753d8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ca92caee-20a6-4c57-95d7-fc8d019fa925">
													<gml:posList>35.25956475477397 139.73780128948985 19.4009 35.259579546768606 139.7377549373104 19.4009 35.25957327228259 139.7377657151043 19.4009 35.25956475477397 139.73780128948985 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:RoofSurface>
					</bldg:boundedBy>
					<bldg:boundedBy>
						<bldg:GroundSurface gml:id="ID_82875b40-dedf-401d-a36e-95e450c3be2c">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_c1421b95-fd17-439a-8cc3-9aeddc1c6552">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d62263eb-e25f-4f6b-ae25-6aa4e338dd37">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_702b5e7a-8dff-4bc6-8a46-9c116fffef22">
													<gml:posList>35.25953108754047 139.73820553543945 10.385279799663763 35.25934551376892 139.73801401031633 10.385279799663763 35.259443288515165 139.7378731949204 10.385279799663763 35.2594409612081 139.73787037637467 10.385279799663763 35.259404996429865 139.73783449243757 10.385279799663763 35.25941485847638 139.73782017117338 10.385279799663763 35.259424720521174 139.73780584990573 10.385279799663763 35.25946290811946 139.73784493865537 10.385279799663763 35.25961723077406 139.73762268148525 10.385279799663763 35.25995567900424 139.73797199382997 10.385279799663763 35.25981983918423 139.73816767808688 10.385279799663763 35.25968399904368 139.73836336169092 10.385279799663763 35.25962468177446 139.73830216921843 10.385279799663763 35.25956536447386 139.73824097683504 10.385279799663763 35.259548226008484 139.73822325613352 10.385279799663763 35.25953108754047 139.73820553543945 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:GroundSurface>
					</bldg:boundedBy>
					<bldg:boundedBy>
						<bldg:WallSurface gml:id="ID_cb2783ce-f745-4531-ba03-78c2d7a1ab79">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_c8abeaf7-829d-405c-822f-5ac0ff3ae0d2">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bf5e79b4-6120-4a85-a664-1020a3491925">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5653b419-561f-46a4-be5c-080425ccaf7c">
													<gml:posList>35.25934551376892 139.73801401031633 17.918 35.259443288515165 139.7378731949204 17.918 35.259443288515165 139.7378731949204 10.385279799663763 35.25934551376892 139.73801401031633 10.385279799663763 35.25934551376892 139.73801401031633 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_29cd4f7d-87c5-498a-8a7f-bd2b910e565b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5ae7fe70-f2db-401b-8b4c-15e9e55dc6d6">
													<gml:posList>35.25953108754047 139.73820553543945 17.918 35.25934551376892 139.73801401031633 17.918 35.25934551376892 139.73801401031633 10.385279799663763 35.25953108754047 139.73820553543945 10.385279799663763 35.25953108754047 139.73820553543945 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_279653dc-0bb5-46fb-ad4f-fc75accad52a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b951b48e-7e0c-47b5-ade6-93caf373021c">
													<gml:posList>35.25956536447386 139.73824097683504 17.918 35.259548226008484 139.73822325613352 10.385279799663763 35.25956536447386 139.73824097683504 10.385279799663763 35.25956536447386 139.73824097683504 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_51152b00-85d4-4c7e-a812-9b63388af164">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_04dc71b5-9e2f-400e-b3ee-9704d63607bc">
													<gml:posList>35.259548226008484 139.73822325613352 10.385279799663763 35.25953108754047 139.73820553543945 17.918 35.25953108754047 139.73820553543945 10.385279799663763 35.259548226008484 139.73822325613352 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_39450ba8-0ff2-4ff7-a9a0-71b0baca74ba">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bbec285c-76a2-4803-97f3-34e7dcbe5893">
													<gml:posList>35.25956536447386 139.73824097683504 17.918 35.25953108754047 139.73820553543945 17.918 35.259548226008484 139.73822325613352 10.385279799663763 35.25956536447386 139.73824097683504 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_dcc3ade8-0952-4294-8f09-c045972e7250">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_84c140f4-fe39-4f54-9570-9238c7713c72">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25962468177446 139.73830216921843 10.385279799663763 35.25968399904368 139.73836336169092 10.385279799663763 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_282d055f-ebe1-47e5-8a2b-a905fba1de21">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c47fcb4f-88fd-480e-a94b-2997bd24ea50">
													<gml:posList>35.25962468177446 139.73830216921843 10.385279799663763 35.25956536447386 139.73824097683504 17.918 35.25956536447386 139.73824097683504 10.385279799663763 35.25962468177446 139.73830216921843 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a20cf19a-e6e5-4c9c-a68b-04aea1071580">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aee721c2-3d44-4d27-b830-514b3e89cf32">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25956536447386 139.73824097683504 17.918 35.25962468177446 139.73830216921843 10.385279799663763 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7c61cf30-28ba-498b-9121-151cbc956dec">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_51caf8af-447b-464c-9a02-67213ae8926c">
													<gml:posList>35.25981983918423 139.73816767808688 10.385279799663763 35.25995567900424 139.73797199382997 10.385279799663763 35.25995567900424 139.73797199382997 17.918 35.25981983918423 139.73816767808688 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1df6536a-725c-445c-8058-e04913fb3084">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_60ca8c55-1097-429b-9185-8e066e910e5b">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25968399904368 139.73836336169092 10.385279799663763 35.25981983918423 139.73816767808688 10.385279799663763 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_111de86d-6af9-4709-a53c-ac1bf9126ea6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5ff6ff0d-26bd-4792-939d-f5d3b545507f">
													<gml:posList>35.25968399904368 139.73836336169092 17.918 35.25981983918423 139.73816767808688 10.385279799663763 35.25995567900424 139.73797199382997 17.918 35.25968399904368 139.73836336169092 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3ac25a20-5823-49ff-bede-5278ba5ad1a3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2a1fc596-4d04-433c-bc77-eb8460f985be">
													<gml:posList>35.25995567900424 139.73797199382997 10.385279799663763 35.25961723077406 139.73762268148525 10.385279799663763 35.25961723077406 139.73762268148525 17.918 35.25995567900424 139.73797199382997 17.918 35.25995567900424 139.73797199382997 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_703e859c-94cd-49d2-bc10-143f2a11a3ff">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e83a306e-9584-4a21-ad6d-b983d71b183a">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.25961723077406 139.73762268148525 17.918 35.25961723077406 139.73762268148525 10.385279799663763 35.25946290811946 139.73784493865537 10.385279799663763 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_867ad6fe-c475-4ea6-8494-d6b4542268d0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f5ced7e2-afc6-412e-85ef-31473dead4be">
													<gml:posList>35.259404996429865 139.73783449243757 19.4009 35.25941485847638 139.73782017117338 10.385279799663763 35.259404996429865 139.73783449243757 10.385279799663763 35.259404996429865 139.73783449243757 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3b750972-c3aa-4136-b1f5-34f608d70a26">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e5505f86-b975-411b-94b3-1eb198739cba">
													<gml:posList>35.25941485847638 139.73782017117338 10.385279799663763 35.259424720521174 139.73780584990573 19.4009 35.259424720521174 139.73780584990573 10.385279799663763 35.25941485847638 139.73782017117338 10.385279799663763</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b3986b6e-09fe-4832-81f3-c1b6350370dc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1b582cab-b61e-4623-a74c-d66c73b64754">
													<gml:posList>35.259404996429865 139.73783449243757 19.4009 35.259424720521174 139.73780584990573 19.4009 35.25941485847638 139.73782017117338 10.385279799663763 35.259404996429865 139.73783449243757 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c29467c1-6d55-414a-8f52-3ecd291e9673">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_90d47977-bcde-4ba9-af64-320652d994ce">
													<gml:posList>35.2594409612081 139.73787037637467 19.4009 35.259404996429865 139.73783449243757 19.4009 35.259404996429865 139.73783449243757 10.385279799663763 35.2594409612081 139.73787037637467 10.385279799663763 35.2594409612081 139.73787037637467 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_74ca698c-989c-4f7b-a8cd-700825e0dce8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b5b549b0-fc30-4fb3-b036-73ac536e7bf9">
													<gml:posList>35.259622516203756 139.73821140379226 17.918 35.25968152899156 139.7381259186416 17.918 35.25968152899156 139.7381259186416 21.72735546832999 35.259622516203756 139.73821140379226 21.72735546832999 35.259622516203756 139.73821140379226 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bdfb612e-7e18-466f-9108-0423b568674f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b84a4744-9185-4829-bdff-4cade6204d7f">
													<gml:posList>35.259669844540305 139.73811392890445 19.4009 35.25964103195404 139.7380843635364 19.4009 35.25964103195404 139.7380843635364 21.72735546832999 35.259669844540305 139.73811392890445 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7981ed1e-05c6-4b9a-9e83-47de4d80f240">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e3f1750e-5477-48d8-9d00-cf4c80283bde">
													<gml:posList>35.25968152899156 139.7381259186416 21.72735546832999 35.259669844540305 139.73811392890445 19.4009 35.25964103195404 139.7380843635364 21.72735546832999 35.25968152899156 139.7381259186416 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6d90c528-bb8a-458b-b1ef-df5774d02825">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4378ed45-56fa-471f-abdb-4847d1e163c2">
													<gml:posList>35.25968152899156 139.7381259186416 17.918 35.259669844540305 139.73811392890445 17.918 35.259669844540305 139.73811392890445 19.4009 35.25968152899156 139.7381259186416 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8c037733-a060-4ee8-932c-25e20649a3f2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b7402cc8-3c37-49d4-8267-1aaa667e7614">
													<gml:posList>35.25968152899156 139.7381259186416 21.72735546832999 35.25968152899156 139.7381259186416 17.918 35.259669844540305 139.73811392890445 19.4009 35.25968152899156 139.7381259186416 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2964f994-7372-436b-84eb-08d4bdd657ff">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d6a4e2dc-e90a-4b9f-8f6c-ed64a5284665">
													<gml:posList>35.25958201919518 139.7381698486745 17.918 35.259590402061896 139.73815770537246 19.4009 35.259590402061896 139.73815770537246 17.918 35.25958201919518 139.7381698486745 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a75afab8-00b2-4004-92ff-076859a9612a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b5622c07-21c7-4145-8869-1c1b86717a7e">
													<gml:posList>35.25958201919518 139.7381698486745 21.72735546832999 35.259590402061896 139.73815770537246 19.4009 35.25958201919518 139.7381698486745 17.918 35.25958201919518 139.7381698486745 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_123797db-44fd-4fac-aff1-83949d9b09ce">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c76ca11c-a7c5-451a-95ea-94f6d3eb8b72">
													<gml:posList>35.259590402061896 139.73815770537246 19.4009 35.25964103195404 139.7380843635364 21.72735546832999 35.25964103195404 139.7380843635364 19.4009 35.259590402061896 139.73815770537246 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e08f574a-0c4d-4d45-8ca2-6ff546ca3ca2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ef0d146a-bf69-4d0d-983d-1d6d156fe269">
													<gml:posList>35.25958201919518 139.7381698486745 21.72735546832999 35.25964103195404 139.7380843635364 21.72735546832999 35.259590402061896 139.73815770537246 19.4009 35.25958201919518 139.7381698486745 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_13eec824-4ec8-4768-be0a-7b78ba70f3f1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ec5b6e08-8db4-4051-bbcf-ac5def76ac61">
													<gml:posList>35.259622516203756 139.73821140379226 21.72735546832999 35.25958201919518 139.7381698486745 21.72735546832999 35.25958201919518 139.7381698486745 17.918 35.259622516203756 139.73821140379226 17.918 35.259622516203756 139.73821140379226 21.72735546832999</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f55de937-5c0a-417a-919f-e5d4d361467f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_805b018d-2dc8-405e-a5d6-cb91d9de408d">
													<gml:posList>35.25967066445761 139.7380758993473 17.918 35.2596575322844 139.73804374627193 17.918 35.2596575322844 139.73804374627193 19.4009 35.25967066445761 139.7380758993473 19.4009 35.25967066445761 139.7380758993473 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a1f10f51-d029-44e4-ba2d-c0fa7993f385">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6f79352a-401b-4cd2-be50-97101ce9cb0f">
													<gml:posList>35.2596575322844 139.73804374627193 17.918 35.25965537224956 139.7380366271229 17.918 35.25965537224956 139.7380366271229 19.4009 35.2596575322844 139.73804374627193 19.4009 35.2596575322844 139.73804374627193 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0ab91067-88ca-4398-9f69-1d4697d32af5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3b9fa3cf-3798-42e9-b4c9-ca1d698f35e6">
													<gml:posList>35.25965537224956 139.7380366271229 17.918 35.25965338261245 139.73802839776027 17.918 35.25965338261245 139.73802839776027 19.4009 35.25965537224956 139.7380366271229 19.4009 35.25965537224956 139.7380366271229 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1d66e3d1-f665-4748-98eb-e93cac86663b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8a52c8fa-bfcc-4882-85d8-3261b1a6a280">
													<gml:posList>35.25965338261245 139.73802839776027 17.918 35.259652440862574 139.73802299166348 17.918 35.259652440862574 139.73802299166348 19.4009 35.25965338261245 139.73802839776027 19.4009 35.25965338261245 139.73802839776027 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ab6b87f8-ef1c-4db5-96c7-6a60ccad5b66">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8008e650-0e6c-47a4-ade3-7377ce731494">
													<gml:posList>35.259652440862574 139.73802299166348 17.918 35.25965208378042 139.73801598030684 17.918 35.25965208378042 139.73801598030684 19.4009 35.259652440862574 139.73802299166348 19.4009 35.259652440862574 139.73802299166348 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_57cad793-dd72-486a-8b13-c0eb8449d86a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c5e3b7ba-cb36-40ab-8c82-5085b10145fa">
													<gml:posList>35.25965208378042 139.73801598030684 17.918 35.259652466124535 139.73800928680149 17.918 35.259652466124535 139.73800928680149 19.4009 35.25965208378042 139.73801598030684 19.4009 35.25965208378042 139.73801598030684 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0cb1a79a-fd64-4c2b-9d84-0c0c56565385">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d64d7946-c92c-48a8-9de1-7cbae738c4dd">
													<gml:posList>35.259652466124535 139.73800928680149 17.918 35.25965316428178 139.73800298857495 17.918 35.25965316428178 139.73800298857495 19.4009 35.259652466124535 139.73800928680149 19.4009 35.259652466124535 139.73800928680149 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0d1e32b5-e617-4b29-b8e6-2cceebfce8d7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_398fb8a6-e77f-4383-862d-33ed53c86c5d">
													<gml:posList>35.25965316428178 139.73800298857495 17.918 35.25965435017399 139.73799790969406 17.918 35.25965435017399 139.73799790969406 19.4009 35.25965316428178 139.73800298857495 19.4009 35.25965316428178 139.73800298857495 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9173b8a6-591f-4382-aa84-658dbd8865ba">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1ddf3789-4dc3-4fa3-b8f9-0d9070ab3ca4">
													<gml:posList>35.25965435017399 139.73799790969406 17.918 35.25965619403464 139.73799273113025 17.918 35.25965619403464 139.73799273113025 19.4009 35.25965435017399 139.73799790969406 19.4009 35.25965435017399 139.73799790969406 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_37d5d573-2ee6-406e-925d-07d3621751e5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6cf8bd54-a915-4f23-a42b-4d7aabd0d7e5">
													<gml:posList>35.25965619403464 139.73799273113025 17.918 35.259658939727075 139.73798805706116 17.918 35.259658939727075 139.73798805706116 19.4009 35.25965619403464 139.73799273113025 19.4009 35.25965619403464 139.73799273113025 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_55ece02d-a026-41e5-b297-841230dcea6e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6180da2c-446f-438f-b08d-4c75f81a17ba">
													<gml:posList>35.259658939727075 139.73798805706116 17.918 35.259662676381495 139.73798260152373 17.918 35.259662676381495 139.73798260152373 19.4009 35.259658939727075 139.73798805706116 19.4009 35.259658939727075 139.73798805706116 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_24344210-c5ff-444a-b613-5c640cf39ef2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1096ae1f-0306-4fd4-965c-e8c8bb944f88">
													<gml:posList>35.259662676381495 139.73798260152373 17.918 35.25966688303696 139.73797873902072 17.918 35.25966688303696 139.73797873902072 19.4009 35.259662676381495 139.73798260152373 19.4009 35.259662676381495 139.73798260152373 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_023ea151-15ba-479f-b7f1-31d5fd814c7b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f77756e7-81c6-4199-b4c0-0d0752377342">
													<gml:posList>35.25966688303696 139.73797873902072 17.918 35.25967126129378 139.7379752939456 17.918 35.25967126129378 139.7379752939456 19.4009 35.25966688303696 139.73797873902072 19.4009 35.25966688303696 139.73797873902072 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c318874a-d0e1-4859-b02e-655df2db4bff">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_86c9935a-8c17-4e10-b280-15e8a72566c1">
													<gml:posList>35.25967126129378 139.7379752939456 17.918 35.25967792936525 139.7379720659927 17.918 35.25967792936525 139.7379720659927 19.4009 35.25967126129378 139.7379752939456 19.4009 35.25967126129378 139.7379752939456 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_89e9b7f0-deca-4a1e-aa68-d4243042758b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cf17229c-9435-4969-9a1a-39241a4ac757">
													<gml:posList>35.25967792936525 139.7379720659927 17.918 35.25968359802319 139.7379703338836 17.918 35.25968359802319 139.7379703338836 19.4009 35.25967792936525 139.7379720659927 19.4009 35.25967792936525 139.7379720659927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9d3f07d0-8e86-45d2-8f89-2ba807e95fce">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f600105a-95d1-48ae-aa54-bd66b882b663">
													<gml:posList>35.25968359802319 139.7379703338836 17.918 35.25968885319091 139.737970085942 17.918 35.25968885319091 139.737970085942 19.4009 35.25968359802319 139.7379703338836 19.4009 35.25968359802319 139.7379703338836 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_33015dc0-27ce-4ce0-baaa-bf7ed57d2b6d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1b0a59f0-20e6-416e-8bc0-7ed45754cbcf">
													<gml:posList>35.25969377546042 139.73797064067853 19.4009 35.25968885319091 139.737970085942 19.4009 35.25968885319091 139.737970085942 17.918 35.25969377546042 139.73797064067853 17.918 35.25969377546042 139.73797064067853 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6bdb1693-8fd3-4b31-b82f-b173d45e9f68">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_739e97d5-2820-48c4-a493-47738adceecd">
													<gml:posList>35.259699744354364 139.73797241410668 19.4009 35.25969377546042 139.73797064067853 19.4009 35.25969377546042 139.73797064067853 17.918 35.259699744354364 139.73797241410668 17.918 35.259699744354364 139.73797241410668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c745480f-2fd4-421a-b468-66719c46eb93">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1c4edc40-3f10-4209-8df1-3f2a7b578750">
													<gml:posList>35.25970529952417 139.73797537496668 19.4009 35.259699744354364 139.73797241410668 19.4009 35.259699744354364 139.73797241410668 17.918 35.25970529952417 139.73797537496668 17.918 35.25970529952417 139.73797537496668 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_79a2560d-2ef1-4edc-98bb-9aa3d6ce7f16">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4a676d12-5195-4a6b-befe-e26714f5908e">
													<gml:posList>35.25977880916527 139.73802961371203 19.4009 35.25970529952417 139.73797537496668 19.4009 35.25970529952417 139.73797537496668 17.918 35.25977880916527 139.73802961371203 17.918 35.25977880916527 139.73802961371203 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7c95072b-cf70-4846-b703-8a6cf39bdb83">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_42b9d232-43db-460f-8b15-9642771808bd">
													<gml:posList>35.25978477852568 139.73803198061987 19.4009 35.25977880916527 139.73802961371203 19.4009 35.25977880916527 139.73802961371203 17.918 35.25978477852568 139.73803198061987 17.918 35.25978477852568 139.73803198061987 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_73d2211d-ff5e-47dc-bdc8-d60728060f0d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_66a617d4-ac34-4e44-a4be-7b30c96b8519">
													<gml:posList>35.259790675061595 139.73803344641183 19.4009 35.25978477852568 139.73803198061987 19.4009 35.25978477852568 139.73803198061987 17.918 35.259790675061595 139.73803344641183 17.918 35.259790675061595 139.73803344641183 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4a94b719-e220-4513-8ccd-6c7f88c197fa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_604edca7-e67c-4fd4-bec0-64c0c98b276a">
													<gml:posList>35.25979755354563 139.73803413074594 19.4009 35.259790675061595 139.73803344641183 19.4009 35.259790675061595 139.73803344641183 17.918 35.25979755354563 139.73803413074594 17.918 35.25979755354563 139.73803413074594 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_15db1b8f-8710-40c8-b6f8-42cf23e6e4e5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_be85cc1e-36eb-41d7-892b-8497f89ceff7">
													<gml:posList>35.25979755354563 139.73803413074594 17.918 35.25980395362932 139.7380340023607 17.918 35.25980395362932 139.7380340023607 19.4009 35.25979755354563 139.73803413074594 19.4009 35.25979755354563 139.73803413074594 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_40f4e98a-15f2-4103-b3d0-59b596271a6e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d349c3ca-eb3c-4aa4-8888-169ca0487370">
													<gml:posList>35.25980395362932 139.7380340023607 17.918 35.25980921702374 139.73803275429924 17.918 35.25980921702374 139.73803275429924 19.4009 35.25980395362932 139.7380340023607 19.4009 35.25980395362932 139.7380340023607 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_060e077a-61e9-408d-b9fb-d08f02cd5e8b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_33c56267-3164-4192-b6e3-773f935f72fa">
													<gml:posList>35.25980921702374 139.73803275429924 17.918 35.259814731728945 139.7380301211701 17.918 35.259814731728945 139.7380301211701 19.4009 35.25980921702374 139.73803275429924 19.4009 35.25980921702374 139.73803275429924 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d955b05c-73f9-4c37-8e9c-24bb01af3688">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8bb2cff8-7f72-490b-a75c-b37a1ae2846b">
													<gml:posList>35.259814731728945 139.7380301211701 17.918 35.25981959722873 139.73802726899535 17.918 35.25981959722873 139.73802726899535 19.4009 35.259814731728945 139.7380301211701 19.4009 35.259814731728945 139.7380301211701 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e4c6d5b8-fa7d-4615-a318-cfe0edd65ee7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_db981450-922e-4f76-8e90-670de306f087">
													<gml:posList>35.25981959722873 139.73802726899535 17.918 35.259824461949364 139.73802342769727 17.918 35.259824461949364 139.73802342769727 19.4009 35.25981959722873 139.73802726899535 19.4009 35.25981959722873 139.73802726899535 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ea5c3648-6b72-40c0-a434-57ac152441ef">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cef452b2-9e16-441a-bc14-026e9d2cb613">
													<gml:posList>35.259824461949364 139.73802342769727 17.918 35.259829830607025 139.738018486782 17.918 35.259829830607025 139.738018486782 19.4009 35.259824461949364 139.73802342769727 19.4009 35.259824461949364 139.73802342769727 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4afe81aa-7bf9-469d-8c91-99da6e5f7618">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5ff5c296-fb96-44d8-b971-4cb88f3cf993">
													<gml:posList>35.259829830607025 139.738018486782 17.918 35.25983322612906 139.73801482304748 17.918 35.25983322612906 139.73801482304748 19.4009 35.259829830607025 139.738018486782 19.4009 35.259829830607025 139.738018486782 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5877f253-383e-4685-ad88-8ada69841698">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8395b167-0fed-4a36-a311-41dec16b692b">
													<gml:posList>35.25983322612906 139.73801482304748 17.918 35.259837124730936 139.73800897166032 17.918 35.259837124730936 139.73800897166032 19.4009 35.25983322612906 139.73801482304748 19.4009 35.25983322612906 139.73801482304748 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d007f401-b329-4203-84c9-cc9650177701">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_143e12a3-725f-4849-80d8-2b39ff81e2bd">
													<gml:posList>35.259837124730936 139.73800897166032 17.918 35.25984094211692 139.738003010465 17.918 35.25984094211692 139.738003010465 19.4009 35.259837124730936 139.73800897166032 19.4009 35.259837124730936 139.73800897166032 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_259b6588-e2f0-4652-927b-6963f92bd522">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f4fb465a-7157-465c-828b-f40a709d53c7">
													<gml:posList>35.25984094211692 139.738003010465 17.918 35.25984435330329 139.7379963463677 17.918 35.25984435330329 139.7379963463677 19.4009 35.25984094211692 139.738003010465 19.4009 35.25984094211692 139.738003010465 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d80c6c35-3a42-429f-94b5-58ec09bef9c2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_79d1a201-0c11-40fd-b34d-0e06729d3b1b">
													<gml:posList>35.25984435330329 139.7379963463677 17.918 35.2598467011007 139.73799006817467 17.918 35.2598467011007 139.73799006817467 19.4009 35.25984435330329 139.7379963463677 19.4009 35.25984435330329 139.7379963463677 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_84791aae-b4a3-4588-9edb-b2379f122ab3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d3abb7a2-43bd-42fe-b9c0-673caf929258">
													<gml:posList>35.2598467011007 139.73799006817467 17.918 35.25984865931544 139.7379812956465 17.918 35.25984865931544 139.7379812956465 19.4009 35.2598467011007 139.73799006817467 19.4009 35.2598467011007 139.73799006817467 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2e079687-3415-4fd9-b7b1-bec7c7cc2e9c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a871358e-cc93-4337-85f3-d6fb51691595">
													<gml:posList>35.25984865931544 139.7379812956465 17.918 35.259850023986424 139.73797430423687 17.918 35.259850023986424 139.73797430423687 19.4009 35.25984865931544 139.7379812956465 19.4009 35.25984865931544 139.7379812956465 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fa4bde1c-6a79-4adf-886c-fc7560aaf7be">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8fbb1f90-f318-44b5-8d8d-69cb5312e400">
													<gml:posList>35.259850023986424 139.73797430423687 17.918 35.25984999934051 139.73796590770004 17.918 35.25984999934051 139.73796590770004 19.4009 35.259850023986424 139.73797430423687 19.4009 35.259850023986424 139.73797430423687 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e2d9f96a-1049-4c86-9c2e-c196c3357f1d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5892eeed-ad83-4c96-acc4-76effc9a711e">
													<gml:posList>35.25984999934051 139.73796590770004 17.918 35.25984948869948 139.7379585008569 17.918 35.25984948869948 139.7379585008569 19.4009 35.25984999934051 139.73796590770004 19.4009 35.25984999934051 139.73796590770004 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0ba5c2f2-d240-4048-86da-b54439230f69">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_faef2b3c-30ba-4067-bb3a-fc9daeba58d8">
													<gml:posList>35.25984948869948 139.7379585008569 17.918 35.259848384125355 139.7379523805712 17.918 35.259848384125355 139.7379523805712 19.4009 35.25984948869948 139.7379585008569 19.4009 35.25984948869948 139.7379585008569 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_54f0f5ec-4a79-456c-a9b8-6357ad8e8af0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2df7d2dd-1308-4869-b2eb-6a7deffc66b1">
													<gml:posList>35.259848384125355 139.7379523805712 17.918 35.259846702555414 139.73794616204933 17.918 35.259846702555414 139.73794616204933 19.4009 35.259848384125355 139.7379523805712 19.4009 35.259848384125355 139.7379523805712 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a95f895b-d3fe-4599-a6d6-aa56c8e55271">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_83b826d7-249a-415d-b415-6ced6d23432f">
													<gml:posList>35.259846702555414 139.73794616204933 17.918 35.25984429113582 139.73794034003262 17.918 35.25984429113582 139.73794034003262 19.4009 35.259846702555414 139.73794616204933 19.4009 35.259846702555414 139.73794616204933 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3feeab2c-ad32-470e-8803-08c7bda1eb1f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0b14d44a-1b84-4e7b-a6fe-205d2adfe217">
													<gml:posList>35.25984429113582 139.73794034003262 17.918 35.25984210640868 139.73793621025192 17.918 35.25984210640868 139.73793621025192 19.4009 35.25984429113582 139.73794034003262 19.4009 35.25984429113582 139.73794034003262 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0626b043-3092-4bc6-904e-84a65a05e64b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c503570d-db5c-4727-89eb-f04c729b0b4f">
													<gml:posList>35.25984210640868 139.73793621025192 17.918 35.259838866050906 139.7379308727791 17.918 35.259838866050906 139.7379308727791 19.4009 35.25984210640868 139.73793621025192 19.4009 35.25984210640868 139.73793621025192 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_537f3bd8-60e6-44f3-a163-b3d89feb31ce">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9ba4bbcf-6811-4b69-9938-5e1e594604dd">
													<gml:posList>35.259838866050906 139.7379308727791 17.918 35.25983513867611 139.73792522814998 17.918 35.25983513867611 139.73792522814998 19.4009 35.259838866050906 139.7379308727791 19.4009 35.259838866050906 139.7379308727791 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f44e6eef-14c6-476f-bcda-fac23ca0f5dd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_96772808-b0a5-459c-8834-6cc9b93aca27">
													<gml:posList>35.25983513867611 139.73792522814998 17.918 35.25983115028391 139.73792008937957 17.918 35.25983115028391 139.73792008937957 19.4009 35.25983513867611 139.73792522814998 19.4009 35.25983513867611 139.73792522814998 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5d9c8b95-bd18-455d-924e-6307286c47d9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1846283d-f800-4569-aeb1-e9c5df744437">
													<gml:posList>35.25983115028391 139.73792008937957 17.918 35.25982691936237 139.7379160389303 17.918 35.25982691936237 139.7379160389303 19.4009 35.25983115028391 139.73792008937957 19.4009 35.25983115028391 139.73792008937957 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ae2e33dd-b74b-4d06-bf32-938a7ed72156">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_501f524b-7976-42e3-bad1-d37ac6064f4b">
													<gml:posList>35.25982691936237 139.7379160389303 17.918 35.25982030831789 139.73791156265102 17.918 35.25982030831789 139.73791156265102 19.4009 35.25982691936237 139.7379160389303 19.4009 35.25982691936237 139.7379160389303 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5814bbdc-3cc2-4b26-a668-7d205daf7bb0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0075f6bd-6a55-46b6-8502-649823d8bb5f">
													<gml:posList>35.25982030831789 139.73791156265102 17.918 35.25981377002061 139.73790788857642 17.918 35.25981377002061 139.73790788857642 19.4009 35.25982030831789 139.73791156265102 19.4009 35.25982030831789 139.73791156265102 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bf35d5e4-b76d-4d26-ad3a-fcd01c0d70e7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9c3ac80b-5c49-41a5-a685-08b2e2b90802">
													<gml:posList>35.25981377002061 139.73790788857642 17.918 35.25980821523928 139.73790542227852 17.918 35.25980821523928 139.73790542227852 19.4009 35.25981377002061 139.73790788857642 19.4009 35.25981377002061 139.73790788857642 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cb11bb2d-94f7-47c7-b375-0e568b2d3899">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_db28c325-acbc-4898-90a9-62f6e92b62a3">
													<gml:posList>35.25980821523928 139.73790542227852 17.918 35.259803301117174 139.73790376850937 17.918 35.259803301117174 139.73790376850937 19.4009 35.25980821523928 139.73790542227852 19.4009 35.25980821523928 139.73790542227852 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e88c5ae1-b246-485d-9d6b-64daff17dd67">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cccfa4b2-ccc5-4708-abb0-2f23f787cc04">
													<gml:posList>35.259803301117174 139.73790376850937 17.918 35.25979732391873 139.73790289629525 17.918 35.25979732391873 139.73790289629525 19.4009 35.259803301117174 139.73790376850937 19.4009 35.259803301117174 139.73790376850937 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ec54f690-f8f3-41c6-9c95-5b70b61f8233">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d85c280b-3334-4b36-b0f9-1a6f109d8bc8">
													<gml:posList>35.25979732391873 139.73790289629525 17.918 35.25979150052736 139.7379027382679 17.918 35.25979150052736 139.7379027382679 19.4009 35.25979732391873 139.73790289629525 19.4009 35.25979732391873 139.73790289629525 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ad81890a-3639-4041-9b8e-ea8cc03bc98a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7aed0138-7b6f-4cbd-b32e-755ef45a8db0">
													<gml:posList>35.25978517302655 139.73790346005242 19.4009 35.25979150052736 139.7379027382679 19.4009 35.25979150052736 139.7379027382679 17.918 35.25978517302655 139.73790346005242 17.918 35.25978517302655 139.73790346005242 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8c0bc0bf-f5f0-41f0-8a47-d2697b5dc801">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7957f73e-fdba-4138-8b36-9168eb2e1deb">
													<gml:posList>35.25973399693007 139.73791278482804 19.4009 35.25978517302655 139.73790346005242 19.4009 35.25978517302655 139.73790346005242 17.918 35.25973399693007 139.73791278482804 17.918 35.25973399693007 139.73791278482804 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5cf54d22-e1b3-49ed-9fbe-9301e80a8df0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_86169fbd-8f65-4cab-ae0d-0a724546ce1e">
													<gml:posList>35.25972734499969 139.73791361689402 19.4009 35.25973399693007 139.73791278482804 19.4009 35.25973399693007 139.73791278482804 17.918 35.25972734499969 139.73791361689402 17.918 35.25972734499969 139.73791361689402 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5c9001dc-c7ed-4edb-b3fc-c4bbd61740aa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_71a7ecb1-4cdc-499a-8ae9-18a7fb3310b9">
													<gml:posList>35.25972734499969 139.73791361689402 17.918 35.2597223418349 139.7379133589924 17.918 35.2597223418349 139.7379133589924 19.4009 35.25972734499969 139.73791361689402 19.4009 35.25972734499969 139.73791361689402 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0bbafa17-137c-444d-a09e-ac4140861f4d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8145e68a-d969-410b-96a9-f5d7c87d38ce">
													<gml:posList>35.2597223418349 139.7379133589924 17.918 35.2597173468958 139.73791210096826 17.918 35.2597173468958 139.73791210096826 19.4009 35.2597223418349 139.7379133589924 19.4009 35.2597223418349 139.7379133589924 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5a59cb49-8eda-4a2e-9b89-726dcd71986f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1dc449f8-9209-45dc-8073-5454efa6907d">
													<gml:posList>35.2597173468958 139.73791210096826 17.918 35.25971373011884 139.73790953348902 17.918 35.25971373011884 139.73790953348902 19.4009 35.2597173468958 139.73791210096826 19.4009 35.2597173468958 139.73791210096826 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0c90b213-abf4-4ed4-a5a5-a4a04d270412">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_96a311fe-45a1-40f0-900e-651e148b6f0b">
													<gml:posList>35.25971373011884 139.73790953348902 17.918 35.25970937292682 139.73790539527212 17.918 35.25970937292682 139.73790539527212 19.4009 35.25971373011884 139.73790953348902 19.4009 35.25971373011884 139.73790953348902 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ab898cb2-ff8a-4da5-8524-a829efb1751b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7745e539-e155-4d79-8f69-1d9f775724d9">
													<gml:posList>35.25970937292682 139.73790539527212 17.918 35.25970579949657 139.7379006406829 17.918 35.25970579949657 139.7379006406829 19.4009 35.25970937292682 139.73790539527212 19.4009 35.25970937292682 139.73790539527212 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_57a1b441-3a2c-4502-a928-aa3e523c370e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ab6c0e46-9e6a-43d9-87d5-3fa67c21b6d2">
													<gml:posList>35.25970579949657 139.7379006406829 17.918 35.25970250365558 139.73789353385533 17.918 35.25970250365558 139.73789353385533 19.4009 35.25970579949657 139.7379006406829 19.4009 35.25970579949657 139.7379006406829 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3beb5bb2-9514-472e-bca2-b5f6191091e5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1756cd6f-329d-4a41-b2ea-62704cdf1e4f">
													<gml:posList>35.25970250365558 139.73789353385533 17.918 35.25970101883761 139.7378853368703 17.918 35.25970101883761 139.7378853368703 19.4009 35.25970250365558 139.73789353385533 19.4009 35.25970250365558 139.73789353385533 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9e4276d3-8354-47b5-b16e-fc060390e5b6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_98f3c502-11b0-4a28-92f3-b2b9a06ad0b5">
													<gml:posList>35.25970101883761 139.7378853368703 17.918 35.25970045201622 139.73787528145706 17.918 35.25970045201622 139.73787528145706 19.4009 35.25970101883761 139.7378853368703 19.4009 35.25970101883761 139.7378853368703 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_692b93f3-0efa-41d4-a945-b42d14e231e7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5c0202f6-d4bd-4ef9-bc2f-85fcaa880c35">
													<gml:posList>35.25970045201622 139.73787528145706 17.918 35.25970358105886 139.7378195132624 17.918 35.25970358105886 139.7378195132624 19.4009 35.25970045201622 139.73787528145706 19.4009 35.25970045201622 139.73787528145706 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_106fcf89-9865-43fd-bf13-8766286d4bfa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_85174e9e-3c51-4ff1-b6e0-c489d111f2ed">
													<gml:posList>35.25970358105886 139.7378195132624 17.918 35.25970329143802 139.73780662203973 17.918 35.25970329143802 139.73780662203973 19.4009 35.25970358105886 139.7378195132624 19.4009 35.25970358105886 139.7378195132624 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_437ee112-6d5d-482a-a884-c9005151c3cb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_89b643a0-e081-4fe9-8211-44a8ce925ad4">
													<gml:posList>35.25970329143802 139.73780662203973 17.918 35.259702582237566 139.73779891870717 17.918 35.259702582237566 139.73779891870717 19.4009 35.25970329143802 139.73780662203973 19.4009 35.25970329143802 139.73780662203973 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_39545912-1e90-4493-8a92-682485bab14a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d9035a5e-9c58-424c-a6bf-f59fad4cabd0">
													<gml:posList>35.259702582237566 139.73779891870717 17.918 35.259700330326815 139.73778962359927 17.918 35.259700330326815 139.73778962359927 19.4009 35.259702582237566 139.73779891870717 19.4009 35.259702582237566 139.73779891870717 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_97814ed7-badb-4333-83ed-37f48798dcf5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_82803f5f-5752-4f08-9b88-ec1e52606d8e">
													<gml:posList>35.259700330326815 139.73778962359927 17.918 35.25969742999061 139.7377810985704 17.918 35.25969742999061 139.7377810985704 19.4009 35.259700330326815 139.73778962359927 19.4009 35.259700330326815 139.73778962359927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_de75d1a5-4dc6-477d-ae60-0145844f20b8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d18a4541-a120-45e1-bebd-0fc4a75643d2">
													<gml:posList>35.25969742999061 139.7377810985704 17.918 35.2596947741605 139.7377739909971 17.918 35.2596947741605 139.7377739909971 19.4009 35.25969742999061 139.7377810985704 19.4009 35.25969742999061 139.7377810985704 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b28b9099-ddf4-4917-a579-724789d792e5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_29ec1bb0-d0b0-4de9-addc-3a0402e9506c">
													<gml:posList>35.2596947741605 139.7377739909971 17.918 35.25968777805937 139.7377613494349 17.918 35.25968777805937 139.7377613494349 19.4009 35.2596947741605 139.7377739909971 19.4009 35.2596947741605 139.7377739909971 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f5ceabad-7b49-49e8-8c2a-3d9b45c00b81">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3eb3d4da-1a33-46fd-b400-f15a1e6b7322">
													<gml:posList>35.25968777805937 139.7377613494349 17.918 35.259681398031 139.73775263066943 17.918 35.259681398031 139.73775263066943 19.4009 35.25968777805937 139.7377613494349 19.4009 35.25968777805937 139.7377613494349 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_036e96e5-238c-460a-b6dd-72e817e03ea5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_136e6724-c867-4e5f-87b5-e6e9ce7e69f9">
													<gml:posList>35.259681398031 139.73775263066943 17.918 35.259673610879936 139.7377427925526 17.918 35.259673610879936 139.7377427925526 19.4009 35.259681398031 139.73775263066943 19.4009 35.259681398031 139.73775263066943 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fa82b446-92c8-4c1a-977e-4b79782d163a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_195b7958-1180-4340-a044-b8b690ec89c7">
													<gml:posList>35.259673610879936 139.7377427925526 17.918 35.259666051699966 139.73773626223345 17.918 35.259666051699966 139.73773626223345 19.4009 35.259673610879936 139.7377427925526 19.4009 35.259673610879936 139.7377427925526 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ad7b31f9-85f5-4561-9b13-0fdafa3c0601">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7dfa9a09-24e9-4330-abde-b74f0deac9e7">
													<gml:posList>35.259666051699966 139.73773626223345 17.918 35.25965540144442 139.73773080159927 17.918 35.25965540144442 139.73773080159927 19.4009 35.259666051699966 139.73773626223345 19.4009 35.259666051699966 139.73773626223345 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2f38a5ce-b814-4178-899e-772a55d56c5c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3d763b6e-0618-4d75-b63e-e82082ce897b">
													<gml:posList>35.25965540144442 139.73773080159927 17.918 35.2596427960501 139.7377265741697 17.918 35.2596427960501 139.7377265741697 19.4009 35.25965540144442 139.73773080159927 19.4009 35.25965540144442 139.73773080159927 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2b36afcb-b21e-4604-9fe7-7c88fce35042">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_73b56de3-0a6e-4606-b174-a407cbf3ef0b">
													<gml:posList>35.2596427960501 139.7377265741697 17.918 35.25963146367433 139.73772487300138 17.918 35.25963146367433 139.73772487300138 19.4009 35.2596427960501 139.7377265741697 19.4009 35.2596427960501 139.7377265741697 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ee4e820d-fa74-4797-b676-881ddfced74f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_46d9c1fc-27de-4477-882f-281256701825">
													<gml:posList>35.25962115129924 139.7377249180835 19.4009 35.25963146367433 139.73772487300138 19.4009 35.25963146367433 139.73772487300138 17.918 35.25962115129924 139.7377249180835 17.918 35.25962115129924 139.7377249180835 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1e9d7ed0-b471-48bd-93ba-94032169ac0f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9a9aec47-395d-472d-98d3-6c7759c3e9c2">
													<gml:posList>35.259612364222654 139.7377273352654 19.4009 35.25962115129924 139.7377249180835 19.4009 35.25962115129924 139.7377249180835 17.918 35.259612364222654 139.7377273352654 17.918 35.259612364222654 139.7377273352654 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6af31343-7b80-42a5-a4dc-0e0bceab91c5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c276e746-877c-476e-9fce-444b1b4334c2">
													<gml:posList>35.259604344979664 139.73773179572896 19.4009 35.259612364222654 139.7377273352654 19.4009 35.259612364222654 139.7377273352654 17.918 35.259604344979664 139.73773179572896 17.918 35.259604344979664 139.73773179572896 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7c9d2de1-ea4a-4380-8ce1-c5a1d35c193e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ba575472-58df-4d00-bb3f-f194b3684fb8">
													<gml:posList>35.25959474983381 139.73773829123564 19.4009 35.259604344979664 139.73773179572896 19.4009 35.259604344979664 139.73773179572896 17.918 35.25959474983381 139.73773829123564 17.918 35.25959474983381 139.73773829123564 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b5f1bba9-1bb1-48ae-9520-6bf75e73d5fd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2a13dd95-7ebf-46b9-a093-777ef4737224">
													<gml:posList>35.25958721923983 139.73774512501384 19.4009 35.25959474983381 139.73773829123564 19.4009 35.25959474983381 139.73773829123564 17.918 35.25958721923983 139.73774512501384 17.918 35.25958721923983 139.73774512501384 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c1451626-2883-4115-89b9-605b114fc2db">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_556659ca-4788-48c6-aa5a-f5c298638900">
													<gml:posList>35.259579546768606 139.7377549373104 19.4009 35.25958721923983 139.73774512501384 19.4009 35.25958721923983 139.73774512501384 17.918 35.259579546768606 139.7377549373104 17.918 35.259579546768606 139.7377549373104 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_97fc8ad3-3797-48c3-88d8-84dd15174331">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_22e52c47-4b3b-4f08-8033-c7c15d6be5c0">
													<gml:posList>35.25957327228259 139.7377657151043 19.4009 35.259579546768606 139.7377549373104 19.4009 35.259579546768606 139.7377549373104 17.918 35.25957327228259 139.7377657151043 17.918 35.25957327228259 139.7377657151043 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_25bf7c49-485a-4b69-ae17-3ddcf8394f39">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8307855c-0984-4949-bb9c-5c7e7912786c">
													<gml:posList>35.259568287349126 139.7377771288163 19.4009 35.25957327228259 139.7377657151043 19.4009 35.25957327228259 139.7377657151043 17.918 35.259568287349126 139.7377771288163 17.918 35.259568287349126 139.7377771288163 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_66e241d4-a739-40b9-8638-4149113a7399">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dacc89e8-1843-4f5b-a70e-97cb904017e2">
													<gml:posList>35.259565888566 139.73778731957597 19.4009 35.259568287349126 139.7377771288163 19.4009 35.259568287349126 139.7377771288163 17.918 35.259565888566 139.73778731957597 17.918 35.259565888566 139.73778731957597 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_90863f45-d3c2-45e9-9d66-38f926d2f774">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3e229c54-ab8b-41d7-8cb9-af14e2b88468">
													<gml:posList>35.25956475477397 139.73780128948985 19.4009 35.259565888566 139.73778731957597 19.4009 35.259565888566 139.73778731957597 17.918 35.25956475477397 139.73780128948985 17.918 35.25956475477397 139.73780128948985 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e4ef454a-576b-419b-b8cf-1f2940d2307a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_889858ad-3462-442e-9b11-960c71a16089">
													<gml:posList>35.259565011686625 139.73781842295804 19.4009 35.25956475477397 139.73780128948985 19.4009 35.25956475477397 139.73780128948985 17.918 35.259565011686625 139.73781842295804 17.918 35.259565011686625 139.73781842295804 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bc424dd5-5d97-412f-a47f-1d2f748c1a8d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d423679e-fe55-40b9-a445-7361d95fbadb">
													<gml:posList>35.25956674088509 139.73782787252776 19.4009 35.259565011686625 139.73781842295804 19.4009 35.259565011686625 139.73781842295804 17.918 35.25956674088509 139.73782787252776 17.918 35.25956674088509 139.73782787252776 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9d21be41-8028-440c-88bb-701c0bdb1b6f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0dbc090c-60d5-4b3f-ab8e-0deae541ea83">
													<gml:posList>35.25956863825879 139.7378333983881 19.4009 35.25956674088509 139.73782787252776 19.4009 35.25956674088509 139.73782787252776 17.918 35.25956863825879 139.7378333983881 17.918 35.25956863825879 139.7378333983881 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fbacdf60-6a5f-4b5e-bd46-02dbb6223b95">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e1ec1d1e-851c-4249-ac44-d7fb67b2173c">
													<gml:posList>35.25957140349773 139.73784207742708 19.4009 35.25956863825879 139.7378333983881 19.4009 35.25956863825879 139.7378333983881 17.918 35.25957140349773 139.73784207742708 17.918 35.25957140349773 139.73784207742708 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fd5bc2fd-dfa0-4318-8877-c0d7e7339e28">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9e86c9d3-fc25-4e74-9eec-d4727df37559">
													<gml:posList>35.259607562148425 139.73790188784028 19.4009 35.25957140349773 139.73784207742708 19.4009 35.25957140349773 139.73784207742708 17.918 35.259607562148425 139.73790188784028 17.918 35.259607562148425 139.73790188784028 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4d6be433-4db1-461a-962a-fc9250e50423">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_489e6126-11eb-4bcd-96ea-13a1f0c0186a">
													<gml:posList>35.25961162558559 139.73791074120786 19.4009 35.259607562148425 139.73790188784028 19.4009 35.259607562148425 139.73790188784028 17.918 35.25961162558559 139.73791074120786 17.918 35.25961162558559 139.73791074120786 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9b30334b-2aa5-46ad-a9db-e0b6dc02be38">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_47bf60e1-c29b-45b1-b930-2e4874339ea2">
													<gml:posList>35.25961311779565 139.73791688300133 19.4009 35.25961162558559 139.73791074120786 19.4009 35.25961162558559 139.73791074120786 17.918 35.25961311779565 139.73791688300133 17.918 35.25961311779565 139.73791688300133 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c4546fa3-79fd-4beb-8368-971c2ba6c3bf">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9469e013-d8c6-491b-8f10-7d6ae7d3593d">
													<gml:posList>35.25961357483846 139.73792490533882 19.4009 35.25961311779565 139.73791688300133 19.4009 35.25961311779565 139.73791688300133 17.918 35.25961357483846 139.73792490533882 17.918 35.25961357483846 139.73792490533882 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a490b6ab-e5be-4b9d-b23d-becb1e4c5828">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_79b02708-63b0-44cc-879f-95a5f5317da0">
													<gml:posList>35.25961261674252 139.7379330722079 19.4009 35.25961357483846 139.73792490533882 19.4009 35.25961357483846 139.73792490533882 17.918 35.25961261674252 139.7379330722079 17.918 35.25961261674252 139.7379330722079 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8844132e-646a-4bb2-948c-65a2f0518d6a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_19f35bc5-8d5d-472c-9c98-a068b31fd329">
													<gml:posList>35.259609584950034 139.73794073595585 19.4009 35.25961261674252 139.7379330722079 19.4009 35.25961261674252 139.7379330722079 17.918 35.259609584950034 139.73794073595585 17.918 35.259609584950034 139.73794073595585 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_693572ec-8371-4ff1-b5f3-186efb3c2ccb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3062b170-8041-4645-90a8-91deccb032e6">
													<gml:posList>35.25960347874844 139.73794774389137 19.4009 35.259609584950034 139.73794073595585 19.4009 35.259609584950034 139.73794073595585 17.918 35.25960347874844 139.73794774389137 17.918 35.25960347874844 139.73794774389137 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f0adc3cc-0d5d-4126-9da6-fc2ed03d4baf">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1ee5ba10-0b5c-44bd-8f69-95fcf378b855">
													<gml:posList>35.25959506323896 139.7379526773771 19.4009 35.25960347874844 139.73794774389137 19.4009 35.25960347874844 139.73794774389137 17.918 35.25959506323896 139.7379526773771 17.918 35.25959506323896 139.7379526773771 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a80acf9e-25ac-4630-86a6-1356a2ff2bf1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_10deda04-11d6-4962-9ab5-442ea978bea9">
													<gml:posList>35.25958757311341 139.7379536862642 19.4009 35.25959506323896 139.7379526773771 19.4009 35.25959506323896 139.7379526773771 17.918 35.25958757311341 139.7379536862642 17.918 35.25958757311341 139.7379536862642 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cae4d7bc-a7b9-4374-873a-ae97d219f7e4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_dbbf2218-6850-4a4d-9f21-c8c12ac4a777">
													<gml:posList>35.25958757311341 139.7379536862642 17.918 35.259580504322734 139.73795172729461 17.918 35.259580504322734 139.73795172729461 19.4009 35.25958757311341 139.7379536862642 19.4009 35.25958757311341 139.7379536862642 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_33cd4bf5-4a33-47ba-b710-59f661ae4dfa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a7a1f1dd-0ed0-4929-b04b-e4b92805b102">
													<gml:posList>35.259580504322734 139.73795172729461 17.918 35.25956587536673 139.73794197411962 17.918 35.25956587536673 139.73794197411962 19.4009 35.259580504322734 139.73795172729461 19.4009 35.259580504322734 139.73795172729461 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c78562b7-b31f-4de3-8b5b-c51b492a710c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cdf80310-0fd9-4c5d-84e0-cb4d5cb5e745">
													<gml:posList>35.25956587536673 139.73794197411962 17.918 35.25954306425423 139.7379244274751 17.918 35.25954306425423 139.7379244274751 19.4009 35.25956587536673 139.73794197411962 19.4009 35.25956587536673 139.73794197411962 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f5cb1498-7c0e-40cc-aaae-4e190ad35bcb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5c5b9cf8-ac1f-4279-b50c-476ceadc7ea4">
													<gml:posList>35.25954306425423 139.7379244274751 17.918 35.25952795504885 139.73791152067759 17.918 35.25952795504885 139.73791152067759 19.4009 35.25954306425423 139.7379244274751 19.4009 35.25954306425423 139.7379244274751 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ecd20597-9834-4da0-b305-8e3d256d8f98">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b89cca4d-64ed-436e-b8cc-aff65b18e27f">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.25946290811946 139.73784493865537 10.385279799663763 35.259424720521174 139.73780584990573 10.385279799663763 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a6048a91-3cdb-45aa-95ed-542efb972383">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c7427ebd-39b1-415c-9100-12ec42b9fc56">
													<gml:posList>35.25946290811946 139.73784493865537 17.918 35.259424720521174 139.73780584990573 10.385279799663763 35.259424720521174 139.73780584990573 19.4009 35.25946290811946 139.73784493865537 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_32d13192-3763-459a-a995-f13c0d7ca497">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bfc5ce6f-6bb7-45f0-a2ab-232ca540dd21">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.25952795504885 139.73791152067759 17.918 35.25946290811946 139.73784493865537 17.918 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ca68f407-de63-4d3c-9a5a-2fa1e24ff686">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c195127a-5a81-4a97-8044-bcb9dd1d2497">
													<gml:posList>35.25952795504885 139.73791152067759 19.4009 35.25946290811946 139.73784493865537 17.918 35.259424720521174 139.73780584990573 19.4009 35.25952795504885 139.73791152067759 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a11c8ae8-601f-4a06-9e1b-486b3d1bd22c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2ced1436-bffe-4fff-b7e0-e9595fa6ccbf">
													<gml:posList>35.25945047141383 139.73788189395822 19.4009 35.259443288515165 139.7378731949204 17.918 35.25945047141383 139.73788189395822 17.918 35.25945047141383 139.73788189395822 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e0e45454-f357-426a-8d0c-eaf9d4ff7ab8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0c77d53c-7de7-4870-b0fa-01283f36062f">
													<gml:posList>35.25945047141383 139.73788189395822 19.4009 35.2594409612081 139.73787037637467 19.4009 35.259443288515165 139.7378731949204 17.918 35.25945047141383 139.73788189395822 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e8e18091-09ff-4ecc-84b3-6aa1abdae106">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3e49b2b0-bf91-43d6-bfa3-b681de585f39">
													<gml:posList>35.259443288515165 139.7378731949204 17.918 35.2594409612081 139.73787037637467 10.385279799663763 35.259443288515165 139.7378731949204 10.385279799663763 35.259443288515165 139.7378731949204 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3f27797f-55da-4140-bdd4-12a16f34bbc9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_009e242d-a00d-491c-8ebf-712e18a98d8c">
													<gml:posList>35.259443288515165 139.7378731949204 17.918 35.2594409612081 139.73787037637467 19.4009 35.2594409612081 139.73787037637467 10.385279799663763 35.259443288515165 139.7378731949204 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_311dab8c-3a34-418f-9b5c-00b2c0782197">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f97d2557-d3e1-4824-abc1-928fa9e3b735">
													<gml:posList>35.259453151376654 139.73788531976322 19.4009 35.25945047141383 139.73788189395822 19.4009 35.25945047141383 139.73788189395822 17.918 35.259453151376654 139.73788531976322 17.918 35.259453151376654 139.73788531976322 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1ef118aa-a1c1-42d3-aae1-6037618a9315">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_de9de13b-c651-4663-bdf5-046124839ff7">
													<gml:posList>35.259458495171664 139.73789457825012 19.4009 35.259453151376654 139.73788531976322 19.4009 35.259453151376654 139.73788531976322 17.918 35.259458495171664 139.73789457825012 17.918 35.259458495171664 139.73789457825012 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_41b7d46b-b4f9-455e-a66d-780d284c7783">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6914ee31-543d-4cac-b641-ec041ad8efdf">
													<gml:posList>35.259461962943824 139.7379025201114 19.4009 35.259458495171664 139.73789457825012 19.4009 35.259458495171664 139.73789457825012 17.918 35.259461962943824 139.7379025201114 17.918 35.259461962943824 139.7379025201114 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1d2b2ac3-21d2-409d-83b2-a56d96659fae">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aaa43678-f6a3-436d-9637-93fda7258be4">
													<gml:posList>35.25946380654012 139.7379084416772 19.4009 35.259461962943824 139.7379025201114 19.4009 35.259461962943824 139.7379025201114 17.918 35.25946380654012 139.7379084416772 17.918 35.25946380654012 139.7379084416772 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5ef857c9-525d-4da9-9403-fd94f150892c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_47d63775-16fe-4a40-b2aa-966020bb0f3b">
													<gml:posList>35.25946505755575 139.73791736426713 19.4009 35.25946380654012 139.7379084416772 19.4009 35.25946380654012 139.7379084416772 17.918 35.25946505755575 139.73791736426713 17.918 35.25946505755575 139.73791736426713 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ba2ff89e-1ec6-4db3-aa3a-9859adeeddc1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b355a1ae-bf11-47fd-9f93-c964116158cc">
													<gml:posList>35.25946483731876 139.73792385974363 19.4009 35.25946505755575 139.73791736426713 19.4009 35.25946505755575 139.73791736426713 17.918 35.25946483731876 139.73792385974363 17.918 35.25946483731876 139.73792385974363 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f7dbcc26-dfa9-4414-a4f3-4c7decb454ce">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_39e34b82-271d-4e7a-8524-9c0352240b2f">
													<gml:posList>35.25946421981807 139.73792955339982 19.4009 35.25946483731876 139.73792385974363 19.4009 35.25946483731876 139.73792385974363 17.918 35.25946421981807 139.73792955339982 17.918 35.25946421981807 139.73792955339982 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c90039c9-eb26-46ea-a8d1-b37d4eccae70">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fc646dbc-e495-4635-bb95-ecd255b3a670">
													<gml:posList>35.25946221354603 139.73793453431927 19.4009 35.25946421981807 139.73792955339982 19.4009 35.25946421981807 139.73792955339982 17.918 35.25946221354603 139.73793453431927 17.918 35.25946221354603 139.73793453431927 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9010c58c-1ef4-45d2-9968-1278153e4e63">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2c99655a-e939-46aa-836e-6ff72d54f3f3">
													<gml:posList>35.25944173734013 139.7379744088309 19.4009 35.25946221354603 139.73793453431927 19.4009 35.25946221354603 139.73793453431927 17.918 35.25944173734013 139.7379744088309 17.918 35.25944173734013 139.7379744088309 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8a1079ee-0f22-498e-96df-a4031f5cc413">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5c55af4e-1e30-40d7-a207-9aab71c0c6f0">
													<gml:posList>35.25943863437416 139.73798327057784 19.4009 35.25944173734013 139.7379744088309 19.4009 35.25944173734013 139.7379744088309 17.918 35.25943863437416 139.73798327057784 17.918 35.25943863437416 139.73798327057784 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ef88dfee-df9f-4dd1-85d1-df651468d2af">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a1094a30-c43c-43ab-8166-3d0c24bb8ef4">
													<gml:posList>35.259436261819964 139.7379924501849 19.4009 35.25943863437416 139.73798327057784 19.4009 35.25943863437416 139.73798327057784 17.918 35.259436261819964 139.7379924501849 17.918 35.259436261819964 139.7379924501849 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_780ec64a-2f30-4a40-98f9-d88a0569078c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5baad97e-f515-4cb1-9549-047eec684b48">
													<gml:posList>35.25943511679936 139.73800363956292 19.4009 35.259436261819964 139.7379924501849 19.4009 35.259436261819964 139.7379924501849 17.918 35.25943511679936 139.73800363956292 17.918 35.25943511679936 139.73800363956292 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_14fbcadd-a885-4d72-bcba-2eed9a6c375a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_25ecb170-f03e-4194-a0f2-2fd15d7365ef">
													<gml:posList>35.25943561145207 139.73801364007775 19.4009 35.25943511679936 139.73800363956292 19.4009 35.25943511679936 139.73800363956292 17.918 35.25943561145207 139.73801364007775 17.918 35.25943561145207 139.73801364007775 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_728a94da-a730-42f6-b2b4-1e11388cd20b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b602ca26-8c90-47d2-b7f8-6f3185b770e0">
													<gml:posList>35.25943743820023 139.73802106732313 19.4009 35.25943561145207 139.73801364007775 19.4009 35.25943561145207 139.73801364007775 17.918 35.25943743820023 139.73802106732313 17.918 35.25943743820023 139.73802106732313 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4bb7b17d-0943-4f05-82c3-ad3c5838b9dc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_eddef1e8-f0af-47be-acd1-26c597d98723">
													<gml:posList>35.2594411495849 139.7380293056383 19.4009 35.25943743820023 139.73802106732313 19.4009 35.25943743820023 139.73802106732313 17.918 35.2594411495849 139.7380293056383 17.918 35.2594411495849 139.7380293056383 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4ed60c31-354d-42a3-80d6-035d8e1b435a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_88a3ddfa-7e0e-4720-a953-2f8caf36905e">
													<gml:posList>35.25944512952094 139.73803515876335 19.4009 35.2594411495849 139.7380293056383 19.4009 35.2594411495849 139.7380293056383 17.918 35.25944512952094 139.73803515876335 17.918 35.25944512952094 139.73803515876335 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_87f3dc9f-d829-45a1-a45f-45cb640501c8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4229fce0-2742-4a3d-9f1f-e840c572c8ea">
													<gml:posList>35.25944968558668 139.73804001110494 19.4009 35.25944512952094 139.73803515876335 19.4009 35.25944512952094 139.73803515876335 17.918 35.25944968558668 139.73804001110494 17.918 35.25944968558668 139.73804001110494 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bd2c0fa2-4863-4803-a8ff-433c71f14de4">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6da976f2-7a3a-4c49-87e0-fcf46b7fca93">
													<gml:posList>35.25945580106328 139.73804477370007 19.4009 35.25944968558668 139.73804001110494 19.4009 35.25944968558668 139.73804001110494 17.918 35.25945580106328 139.73804477370007 17.918 35.25945580106328 139.73804477370007 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_902faf81-3925-41a7-9c11-84eac1ddd22b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_03f4d84b-4961-4cd9-88d5-1d655622a449">
													<gml:posList>35.25946119421578 139.7380480424719 19.4009 35.25945580106328 139.73804477370007 19.4009 35.25945580106328 139.73804477370007 17.918 35.25946119421578 139.7380480424719 17.918 35.25946119421578 139.7380480424719 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d98212b6-a6d2-4562-80cc-960ed8c2fb8e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_80c6df41-1f24-4b12-af8f-87d223082379">
													<gml:posList>35.25946643254079 139.73804930021555 19.4009 35.25946119421578 139.7380480424719 19.4009 35.25946119421578 139.7380480424719 17.918 35.25946643254079 139.73804930021555 17.918 35.25946643254079 139.73804930021555 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_e7425049-36b7-4226-b99d-d935de7196c8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5a017c78-8f5c-49e1-abbd-9d41c7cc4b56">
													<gml:posList>35.25947094014199 139.73804984445047 19.4009 35.25946643254079 139.73804930021555 19.4009 35.25946643254079 139.73804930021555 17.918 35.25947094014199 139.73804984445047 17.918 35.25947094014199 139.73804984445047 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5d3c62eb-c94e-4b33-921e-8e82165de11b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_91d2cbe2-3dd3-4cf9-a978-2ed9c0c8f22e">
													<gml:posList>35.25947094014199 139.73804984445047 17.918 35.25953044928078 139.7380453127659 17.918 35.25953044928078 139.7380453127659 19.4009 35.25947094014199 139.73804984445047 19.4009 35.25947094014199 139.73804984445047 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_458cb140-1189-4334-8207-e6c5f6923af5">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ff2d91e7-f0ee-457f-861e-0ac493268e67">
													<gml:posList>35.259536029215894 139.73804538316614 19.4009 35.25953044928078 139.7380453127659 19.4009 35.25953044928078 139.7380453127659 17.918 35.259536029215894 139.73804538316614 17.918 35.259536029215894 139.73804538316614 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f711d49e-6123-4231-82eb-058f556538e9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_bf7003c5-8e20-48ca-97f4-c99f5dec4f0e">
													<gml:posList>35.25954233187303 139.73804745294183 19.4009 35.259536029215894 139.73804538316614 19.4009 35.259536029215894 139.73804538316614 17.918 35.25954233187303 139.73804745294183 17.918 35.25954233187303 139.73804745294183 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_66c57336-030c-457a-bf88-2776f7b1334a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b2ea07e7-c8c7-4727-a895-dc4f48f69854">
													<gml:posList>35.25954861784281 139.73805122622278 19.4009 35.25954233187303 139.73804745294183 19.4009 35.25954233187303 139.73804745294183 17.918 35.25954861784281 139.73805122622278 17.918 35.25954861784281 139.73805122622278 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_773cdf50-7049-4044-a6e3-70b2391abd02">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7287ad85-77b9-4ab1-bce7-c0931c01a7dc">
													<gml:posList>35.2595552208113 139.738056900443 19.4009 35.25954861784281 139.73805122622278 19.4009 35.25954861784281 139.73805122622278 17.918 35.2595552208113 139.738056900443 17.918 35.2595552208113 139.738056900443 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7c325b35-64de-4fd4-b6bf-e12b44d2f9ec">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c385a368-a241-4861-8e09-bbdfcaae75f5">
													<gml:posList>35.25956017477023 139.73806335690034 19.4009 35.2595552208113 139.738056900443 19.4009 35.2595552208113 139.738056900443 17.918 35.25956017477023 139.73806335690034 17.918 35.25956017477023 139.73806335690034 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9acdf131-6bb4-41cf-96a8-7f1f5e11db9d">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_aa884b3c-378f-4fcd-8fa5-21940896c7b9">
													<gml:posList>35.259563885996236 139.7380713974059 19.4009 35.25956017477023 139.73806335690034 19.4009 35.25956017477023 139.73806335690034 17.918 35.259563885996236 139.7380713974059 17.918 35.259563885996236 139.7380713974059 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8dd2339c-3c4d-46a9-9105-9fef71982a18">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5fbe1398-f56d-4e95-b2d4-8e9a14d5f87f">
													<gml:posList>35.25956645200297 139.7380789337016 19.4009 35.259563885996236 139.7380713974059 19.4009 35.259563885996236 139.7380713974059 17.918 35.25956645200297 139.7380789337016 17.918 35.25956645200297 139.7380789337016 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_16a35caa-b81f-489b-ae63-b3d72b11300a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5cb7a812-2cec-4666-97ad-378c3cab3d62">
													<gml:posList>35.25956819784299 139.73808664680107 19.4009 35.25956645200297 139.7380789337016 19.4009 35.25956645200297 139.7380789337016 17.918 35.25956819784299 139.73808664680107 17.918 35.25956819784299 139.73808664680107 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0220353e-9e1c-4944-897b-85ec1fbdbbeb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e3473334-c770-4c71-9d76-2aa2ec086ec1">
													<gml:posList>35.25956951320005 139.73809716291348 19.4009 35.25956819784299 139.73808664680107 19.4009 35.25956819784299 139.73808664680107 17.918 35.25956951320005 139.73809716291348 17.918 35.25956951320005 139.73809716291348 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0b81bce2-8fd8-48d5-8cfe-982bb4bf08ec">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_94ba70e7-8cca-457c-baaa-47f3f9f7f005">
													<gml:posList>35.259569683415414 139.7381072737272 19.4009 35.25956951320005 139.73809716291348 19.4009 35.25956951320005 139.73809716291348 17.918 35.259569683415414 139.7381072737272 17.918 35.259569683415414 139.7381072737272 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9a8c3281-2f7f-461e-8750-ee5c39dfcabb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d680eb34-69e1-4b6d-933a-05907783ca96">
													<gml:posList>35.25956967443283 139.7381187695197 19.4009 35.259569683415414 139.7381072737272 19.4009 35.259569683415414 139.7381072737272 17.918 35.25956967443283 139.7381187695197 17.918 35.25956967443283 139.7381187695197 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_855588b3-8e52-4a43-93d8-45cd6fb52916">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_66a0188b-1bd1-4755-82e8-3f6bbbca5831">
													<gml:posList>35.25957148518652 139.73812879049305 19.4009 35.25956967443283 139.7381187695197 19.4009 35.25956967443283 139.7381187695197 17.918 35.25957148518652 139.73812879049305 17.918 35.25957148518652 139.73812879049305 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b7a13e9a-519f-4376-b7fd-6406fe37fc7a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f62a2c94-5fa7-48b8-ad2e-7acb6bfa8900">
													<gml:posList>35.2595731750611 139.7381341187792 19.4009 35.25957148518652 139.73812879049305 19.4009 35.25957148518652 139.73812879049305 17.918 35.2595731750611 139.7381341187792 17.918 35.2595731750611 139.7381341187792 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b31569a9-5e8d-46fa-bf22-da710f865320">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_33bfac24-78fa-42f7-ae9f-765f92d11ed0">
													<gml:posList>35.2595761636311 139.73814024783388 19.4009 35.2595731750611 139.7381341187792 19.4009 35.2595731750611 139.7381341187792 17.918 35.2595761636311 139.73814024783388 17.918 35.2595761636311 139.73814024783388 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_49ac018f-57f8-407f-b4d0-6fb89a81e340">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_652cc2a4-af5a-4f43-9e99-f6361cd7b38b">
													<gml:posList>35.25958135314272 139.73814820968445 19.4009 35.2595761636311 139.73814024783388 19.4009 35.2595761636311 139.73814024783388 17.918 35.25958135314272 139.73814820968445 17.918 35.25958135314272 139.73814820968445 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d59c678c-edaa-465b-85ea-ba08a39f291b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ddef4cc3-08d6-4d0d-8478-7a40aaa9bfdd">
													<gml:posList>35.25958622269745 139.73815378503826 19.4009 35.25958135314272 139.73814820968445 19.4009 35.25958135314272 139.73814820968445 17.918 35.25958622269745 139.73815378503826 17.918 35.25958622269745 139.73815378503826 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7d5a54b2-dfd5-460d-b2ae-8d072161af69">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_29023068-0eee-496c-8daf-3c454ad646bc">
													<gml:posList>35.259590402061896 139.73815770537246 19.4009 35.25958622269745 139.73815378503826 19.4009 35.25958622269745 139.73815378503826 17.918 35.259590402061896 139.73815770537246 17.918 35.259590402061896 139.73815770537246 19.4009</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5293bac5-caad-4dbf-974d-5f8a873886ab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_28d0008d-b4cb-4b6e-aa61-f0b564317ba2">
													<gml:posList>35.259669844540305 139.73811392890445 17.918 35.259671872505635 139.73811041829376 17.918 35.259671872505635 139.73811041829376 19.4009 35.259669844540305 139.73811392890445 19.4009 35.259669844540305 139.73811392890445 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5a9d687a-f8ae-4989-81b0-16f2d7d3c5e9">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_460b3cf4-2d5a-4474-8d87-72af7c2d2f93">
													<gml:posList>35.259671872505635 139.73811041829376 17.918 35.259673147992196 139.73810463593276 17.918 35.259673147992196 139.73810463593276 19.4009 35.259671872505635 139.73811041829376 19.4009 35.259671872505635 139.73811041829376 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2cfe1a95-b9ae-4e1e-8a4f-bec07ccec2e6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ce680af2-8959-42c9-baa0-8a33e92be8f8">
													<gml:posList>35.259673147992196 139.73810463593276 17.918 35.25967385533306 139.73809854650938 17.918 35.25967385533306 139.73809854650938 19.4009 35.259673147992196 139.73810463593276 19.4009 35.259673147992196 139.73810463593276 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c41cbe7b-c264-456a-b311-a706e1607e74">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_543df8d4-4e69-406d-a359-ff64cfd1c6ec">
													<gml:posList>35.25967385533306 139.73809854650938 17.918 35.25967406679861 139.73809234776354 17.918 35.25967406679861 139.73809234776354 19.4009 35.25967385533306 139.73809854650938 19.4009 35.25967385533306 139.73809854650938 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_efe37995-2696-49c5-8609-02c8836c5fad">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_0df01fe7-c19d-47ce-8b5a-51e022f01cf7">
													<gml:posList>35.25967406679861 139.73809234776354 17.918 35.25967249080396 139.73808282106472 17.918 35.25967249080396 139.73808282106472 19.4009 35.25967406679861 139.73809234776354 19.4009 35.25967406679861 139.73809234776354 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1f4456e0-b44d-4768-98a5-9adfa0e56b11">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fe2dc25b-9a60-442c-bec8-16e809effb6d">
													<gml:posList>35.25967249080396 139.73808282106472 17.918 35.25967066445761 139.7380758993473 17.918 35.25967066445761 139.7380758993473 19.4009 35.25967249080396 139.73808282106472 19.4009 35.25967249080396 139.73808282106472 17.918</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:WallSurface>
					</bldg:boundedBy>
					<uro:buildingIDAttribute>
						<uro:BuildingIDAttribute>
							<uro:buildingID>14201-bldg-156842</uro:buildingID>
							<uro:partID>1</uro:partID>
							<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
							<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
						</uro:BuildingIDAttribute>
					</uro:buildingIDAttribute>
					<uro:buildingDetailAttribute>
						<uro:BuildingDetailAttribute>
							<uro:totalFloorArea uom="m2">3749.39</uro:totalFloorArea>
							<uro:buildingStructureType codeSpace="../../codelists/Building_BuildingStructureType.xml">610</uro:buildingStructureType>
							<uro:buildingStructureOrgType codeSpace="../../codelists/BuildingDetailAttribute_buildingStructureOrgType.xml">2</uro:buildingStructureOrgType>
							<uro:orgUsage2 codeSpace="../../codelists/BuildingDetailAttribute_orgUsage2.xml">134</uro:orgUsage2>
							<uro:surveyYear>2016</uro:surveyYear>
						</uro:BuildingDetailAttribute>
					</uro:buildingDetailAttribute>
					<uro:buildingDisasterRiskAttribute>
						<uro:BuildingLandSlideRiskAttribute>
							<uro:description codeSpace="../../codelists/BuildingLandSlideRiskAttribute_description.xml">1</uro:description>
							<uro:areaType codeSpace="../../codelists/BuildingLandSlideRiskAttribute_areaType.xml">1</uro:areaType>
						</uro:BuildingLandSlideRiskAttribute>
					</uro:buildingDisasterRiskAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">104</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key104.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">105</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key105.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">106</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key106.xml">2</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">107</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key107.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
					<uro:buildingDataQualityAttribute>
						<uro:BuildingDataQualityAttribute>
							<uro:lod1HeightType codeSpace="../../codelists/BuildingDataQualityAttribute_lod1HeightType.xml">6</uro:lod1HeightType>
						</uro:BuildingDataQualityAttribute>
					</uro:buildingDataQualityAttribute>
				</bldg:BuildingPart>
			</bldg:consistsOfBuildingPart>
			<bldg:consistsOfBuildingPart>
				<bldg:BuildingPart gml:id="bldg_a9dcefad-63a0-4fa0-b666-84125640e7a4">
					<gml:name>横須賀美術館</gml:name>
					<gen:intAttribute name="図形ID">
						<gen:value>17464</gen:value>
					</gen:intAttribute>
					<gen:intAttribute name="総建物階数">
						<gen:value>1</gen:value>
					</gen:intAttribute>
					<gen:measureAttribute name="１階床面積">
						<gen:value uom="m2">1106</gen:value>
					</gen:measureAttribute>
					<gen:doubleAttribute name="床面積換算係数">
						<gen:value>0.9</gen:value>
					</gen:doubleAttribute>
					<bldg:usage codeSpace="../../codelists/Building_usage.xml">422</bldg:usage>
					<bldg:measuredHeight uom="m">9.7</bldg:measuredHeight>
					<bldg:storeysAboveGround>1</bldg:storeysAboveGround>
					<bldg:lod0FootPrint>
						<gml:MultiSurface>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259643832141876 139.7385863904485 6.693040636924465 35.2600937445063 139.73793959711526 6.693040636924465 35.26002596206708 139.7378695119702 6.693040636924465 35.259990820546655 139.73792075292218 6.693040636924465 35.25995567900424 139.73797199382997 6.693040636924465 35.25981983918423 139.73816767808688 6.693040636924465 35.25968399904368 139.73836336169092 6.693040636924465 35.25965168052363 139.73840982251252 6.693040636924465 35.25953315941118 139.7382872745984 6.693040636924465 35.25956536447386 139.73824097683504 6.693040636924465 35.259548226008484 139.73822325613352 6.693040636924465 35.25953108754047 139.73820553543945 6.693040636924465 35.259514691221206 139.73822910668326 6.693040636924465 35.25949829489728 139.7382526779176 6.693040636924465 35.259275491687816 139.7380223064613 6.693040636924465 35.2592378493168 139.73807642089898 6.693040636924465 35.25965266456154 139.73850532836764 6.693040636924465 35.25961584798869 139.73855825537126 6.693040636924465 35.25957574100256 139.7385167855726 6.693040636924465 35.25943134072267 139.73872437273238 6.693040636924465 35.25947144763866 139.7387658425601 6.693040636924465 35.259499108064276 139.7387944429737 6.693040636924465 35.25960453960058 139.73864287676795 6.693040636924465 35.25964460292807 139.73868339346177 6.693040636924465 35.25960678762981 139.73873849870526 6.693040636924465 35.25965208476815 139.73878470400086 6.693040636924465 35.25967772500748 139.7387473405317 6.693040636924465 35.25969120476982 139.73876109055558 6.693040636924465 35.25970337985148 139.73874334877107 6.693040636924465 35.25984920694045 139.73889373068548 6.693040636924465 35.25988764397698 139.7388384883027 6.693040636924465 35.259643832141876 139.7385863904485 6.693040636924465</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:MultiSurface>
					</bldg:lod0FootPrint>
					<bldg:lod1Solid>
						<gml:Solid>
							<gml:exterior>
								<gml:CompositeSurface>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259643832141876 139.7385863904485 6.693040636924465 35.25988764397698 139.7388384883027 6.693040636924465 35.25984920694045 139.73889373068548 6.693040636924465 35.25970337985148 139.73874334877107 6.693040636924465 35.25969120476982 139.73876109055558 6.693040636924465 35.25967772500748 139.7387473405317 6.693040636924465 35.25965208476815 139.73878470400086 6.693040636924465 35.25960678762981 139.73873849870526 6.693040636924465 35.25964460292807 139.73868339346177 6.693040636924465 35.25960453960058 139.73864287676795 6.693040636924465 35.259499108064276 139.7387944429737 6.693040636924465 35.25947144763866 139.7387658425601 6.693040636924465 35.25943134072267 139.73872437273238 6.693040636924465 35.25957574100256 139.7385167855726 6.693040636924465 35.25961584798869 139.73855825537126 6.693040636924465 35.25965266456154 139.73850532836764 6.693040636924465 35.2592378493168 139.73807642089898 6.693040636924465 35.259275491687816 139.7380223064613 6.693040636924465 35.25949829489728 139.7382526779176 6.693040636924465 35.259514691221206 139.73822910668326 6.693040636924465 35.25953108754047 139.73820553543945 6.693040636924465 35.259548226008484 139.73822325613352 6.693040636924465 35.25956536447386 139.73824097683504 6.693040636924465 35.25953315941118 139.7382872745984 6.693040636924465 35.25965168052363 139.73840982251252 6.693040636924465 35.25968399904368 139.73836336169092 6.693040636924465 35.25981983918423 139.73816767808688 6.693040636924465 35.25995567900424 139.73797199382997 6.693040636924465 35.259990820546655 139.73792075292218 6.693040636924465 35.26002596206708 139.7378695119702 6.693040636924465 35.2600937445063 139.73793959711526 6.693040636924465 35.259643832141876 139.7385863904485 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259643832141876 139.7385863904485 6.693040636924465 35.2600937445063 139.73793959711526 6.693040636924465 35.2600937445063 139.73793959711526 16.39905526226481 35.259643832141876 139.7385863904485 16.39905526226481 35.259643832141876 139.7385863904485 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.2600937445063 139.73793959711526 6.693040636924465 35.26002596206708 139.7378695119702 6.693040636924465 35.26002596206708 139.7378695119702 16.39905526226481 35.2600937445063 139.73793959711526 16.39905526226481 35.2600937445063 139.73793959711526 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.26002596206708 139.7378695119702 6.693040636924465 35.259990820546655 139.73792075292218 6.693040636924465 35.259990820546655 139.73792075292218 16.39905526226481 35.26002596206708 139.7378695119702 16.39905526226481 35.26002596206708 139.7378695119702 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259990820546655 139.73792075292218 6.693040636924465 35.25995567900424 139.73797199382997 6.693040636924465 35.25995567900424 139.73797199382997 16.39905526226481 35.259990820546655 139.73792075292218 16.39905526226481 35.259990820546655 139.73792075292218 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25995567900424 139.73797199382997 6.693040636924465 35.25981983918423 139.73816767808688 6.693040636924465 35.25981983918423 139.73816767808688 16.39905526226481 35.25995567900424 139.73797199382997 16.39905526226481 35.25995567900424 139.73797199382997 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25981983918423 139.73816767808688 6.693040636924465 35.25968399904368 139.73836336169092 6.693040636924465 35.25968399904368 139.73836336169092 16.39905526226481 35.25981983918423 139.73816767808688 16.39905526226481 35.25981983918423 139.73816767808688 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25968399904368 139.73836336169092 6.693040636924465 35.25965168052363 139.73840982251252 6.693040636924465 35.25965168052363 139.73840982251252 16.39905526226481 35.25968399904368 139.73836336169092 16.39905526226481 35.25968399904368 139.73836336169092 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25965168052363 139.73840982251252 6.693040636924465 35.25953315941118 139.7382872745984 6.693040636924465 35.25953315941118 139.7382872745984 16.39905526226481 35.25965168052363 139.73840982251252 16.39905526226481 35.25965168052363 139.73840982251252 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25953315941118 139.7382872745984 6.693040636924465 35.25956536447386 139.73824097683504 6.693040636924465 35.25956536447386 139.73824097683504 16.39905526226481 35.25953315941118 139.7382872745984 16.39905526226481 35.25953315941118 139.7382872745984 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25956536447386 139.73824097683504 6.693040636924465 35.259548226008484 139.73822325613352 6.693040636924465 35.259548226008484 139.73822325613352 16.39905526226481 35.25956536447386 139.73824097683504 16.39905526226481 35.25956536447386 139.73824097683504 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259548226008484 139.73822325613352 6.693040636924465 35.25953108754047 139.73820553543945 6.693040636924465 35.25953108754047 139.73820553543945 16.39905526226481 35.259548226008484 139.73822325613352 16.39905526226481 35.259548226008484 139.73822325613352 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25953108754047 139.73820553543945 6.693040636924465 35.259514691221206 139.73822910668326 6.693040636924465 35.259514691221206 139.73822910668326 16.39905526226481 35.25953108754047 139.73820553543945 16.39905526226481 35.25953108754047 139.73820553543945 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259514691221206 139.73822910668326 6.693040636924465 35.25949829489728 139.7382526779176 6.693040636924465 35.25949829489728 139.7382526779176 16.39905526226481 35.259514691221206 139.73822910668326 16.39905526226481 35.259514691221206 139.73822910668326 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25949829489728 139.7382526779176 6.693040636924465 35.259275491687816 139.7380223064613 6.693040636924465 35.259275491687816 139.7380223064613 16.39905526226481 35.25949829489728 139.7382526779176 16.39905526226481 35.25949829489728 139.7382526779176 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259275491687816 139.7380223064613 6.693040636924465 35.2592378493168 139.73807642089898 6.693040636924465 35.2592378493168 139.73807642089898 16.39905526226481 35.259275491687816 139.7380223064613 16.39905526226481 35.259275491687816 139.7380223064613 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.2592378493168 139.73807642089898 6.693040636924465 35.25965266456154 139.73850532836764 6.693040636924465 35.25965266456154 139.73850532836764 16.39905526226481 35.2592378493168 139.73807642089898 16.39905526226481 35.2592378493168 139.73807642089898 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25965266456154 139.73850532836764 6.693040636924465 35.25961584798869 139.73855825537126 6.693040636924465 35.25961584798869 139.73855825537126 16.39905526226481 35.25965266456154 139.73850532836764 16.39905526226481 35.25965266456154 139.73850532836764 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25961584798869 139.73855825537126 6.693040636924465 35.25957574100256 139.7385167855726 6.693040636924465 35.25957574100256 139.7385167855726 16.39905526226481 35.25961584798869 139.73855825537126 16.39905526226481 35.25961584798869 139.73855825537126 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25957574100256 139.7385167855726 6.693040636924465 35.25943134072267 139.73872437273238 6.693040636924465 35.25943134072267 139.73872437273238 16.39905526226481 35.25957574100256 139.7385167855726 16.39905526226481 35.25957574100256 139.7385167855726 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25943134072267 139.73872437273238 6.693040636924465 35.25947144763866 139.7387658425601 6.693040636924465 35.25947144763866 139.7387658425601 16.39905526226481 35.25943134072267 139.73872437273238 16.39905526226481 35.25943134072267 139.73872437273238 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25947144763866 139.7387658425601 6.693040636924465 35.259499108064276 139.7387944429737 6.693040636924465 35.259499108064276 139.7387944429737 16.39905526226481 35.25947144763866 139.7387658425601 16.39905526226481 35.25947144763866 139.7387658425601 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259499108064276 139.7387944429737 6.693040636924465 35.25960453960058 139.73864287676795 6.693040636924465 35.25960453960058 139.73864287676795 16.39905526226481 35.259499108064276 139.7387944429737 16.39905526226481 35.259499108064276 139.7387944429737 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25960453960058 139.73864287676795 6.693040636924465 35.25964460292807 139.73868339346177 6.693040636924465 35.25964460292807 139.73868339346177 16.39905526226481 35.25960453960058 139.73864287676795 16.39905526226481 35.25960453960058 139.73864287676795 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25964460292807 139.73868339346177 6.693040636924465 35.25960678762981 139.73873849870526 6.693040636924465 35.25960678762981 139.73873849870526 16.39905526226481 35.25964460292807 139.73868339346177 16.39905526226481 35.25964460292807 139.73868339346177 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25960678762981 139.73873849870526 6.693040636924465 35.25965208476815 139.73878470400086 6.693040636924465 35.25965208476815 139.73878470400086 16.39905526226481 35.25960678762981 139.73873849870526 16.39905526226481 35.25960678762981 139.73873849870526 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25965208476815 139.73878470400086 6.693040636924465 35.25967772500748 139.7387473405317 6.693040636924465 35.25967772500748 139.7387473405317 16.39905526226481 35.25965208476815 139.73878470400086 16.39905526226481 35.25965208476815 139.73878470400086 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25967772500748 139.7387473405317 6.693040636924465 35.25969120476982 139.73876109055558 6.693040636924465 35.25969120476982 139.73876109055558 16.39905526226481 35.25967772500748 139.7387473405317 16.39905526226481 35.25967772500748 139.7387473405317 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25969120476982 139.73876109055558 6.693040636924465 35.25970337985148 139.73874334877107 6.693040636924465 35.25970337985148 139.73874334877107 16.39905526226481 35.25969120476982 139.73876109055558 16.39905526226481 35.25969120476982 139.73876109055558 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25970337985148 139.73874334877107 6.693040636924465 35.25984920694045 139.73889373068548 6.693040636924465 35.25984920694045 139.73889373068548 16.39905526226481 35.25970337985148 139.73874334877107 16.39905526226481 35.25970337985148 139.73874334877107 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25984920694045 139.73889373068548 6.693040636924465 35.25988764397698 139.7388384883027 6.693040636924465 35.25988764397698 139.7388384883027 16.39905526226481 35.25984920694045 139.73889373068548 16.39905526226481 35.25984920694045 139.73889373068548 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.25988764397698 139.7388384883027 6.693040636924465 35.259643832141876 139.7385863904485 6.693040636924465 35.259643832141876 139.7385863904485 16.39905526226481 35.25988764397698 139.7388384883027 16.39905526226481 35.25988764397698 139.7388384883027 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon>
											<gml:exterior>
												<gml:LinearRing>
													<gml:posList>35.259643832141876 139.7385863904485 16.39905526226481 35.2600937445063 139.73793959711526 16.39905526226481 35.26002596206708 139.7378695119702 16.39905526226481 35.259990820546655 139.73792075292218 16.39905526226481 35.25995567900424 139.73797199382997 16.39905526226481 35.25981983918423 139.73816767808688 16.39905526226481 35.25968399904368 139.73836336169092 16.39905526226481 35.25965168052363 139.73840982251252 16.39905526226481 35.25953315941118 139.7382872745984 16.39905526226481 35.25956536447386 139.73824097683504 16.39905526226481 35.259548226008484 139.73822325613352 16.39905526226481 35.25953108754047 139.73820553543945 16.39905526226481 35.259514691221206 139.73822910668326 16.39905526226481 35.25949829489728 139.7382526779176 16.39905526226481 35.259275491687816 139.7380223064613 16.39905526226481 35.2592378493168 139.73807642089898 16.39905526226481 35.25965266456154 139.73850532836764 16.39905526226481 35.25961584798869 139.73855825537126 16.39905526226481 35.25957574100256 139.7385167855726 16.39905526226481 35.25943134072267 139.73872437273238 16.39905526226481 35.25947144763866 139.7387658425601 16.39905526226481 35.259499108064276 139.7387944429737 16.39905526226481 35.25960453960058 139.73864287676795 16.39905526226481 35.25964460292807 139.73868339346177 16.39905526226481 35.25960678762981 139.73873849870526 16.39905526226481 35.25965208476815 139.73878470400086 16.39905526226481 35.25967772500748 139.7387473405317 16.39905526226481 35.25969120476982 139.73876109055558 16.39905526226481 35.25970337985148 139.73874334877107 16.39905526226481 35.25984920694045 139.73889373068548 16.39905526226481 35.25988764397698 139.7388384883027 16.39905526226481 35.259643832141876 139.7385863904485 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:CompositeSurface>
							</gml:exterior>
						</gml:Solid>
					</bldg:lod1Solid>
					<bldg:lod2Solid>
						<gml:Solid gml:id="ID_9d260426-0022-4e73-a75e-5beb37f335d9">
							<gml:exterior>
								<gml:CompositeSurface gml:id="ID_b4295492-1354-4210-b64f-062619b039a6">
									<gml:surfaceMember xlink:href="#ID_cc08403d-b074-4691-a49e-c763be3d2564"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_29cafac6-8b5a-459b-8f1d-143d60949d1e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9c7d1bc6-541a-4e94-9da7-cab97dbc7dcc"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_50d3136b-ab09-4c96-a8cc-d54760caded2"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ac9d4217-7092-4136-8d78-16ed1f4e7b90"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_dd4394c1-5030-43f3-838a-7ffed6f0db44"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_7554e790-b6d3-4c3e-847c-270c96bce7d8"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1ae4cd69-4b5e-405c-bd76-120f7ee9a3f1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_490e9398-0d6d-4ef7-aada-90e65473c2aa"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_ab78d717-15dc-43b3-9355-477fb04845f7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_346fb2ee-40f3-41b6-a0e5-55e7d760f25a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6dd690a9-388d-43bd-8b69-d51e03d7d250"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_c5d91124-7a19-43f7-b333-4304a0cc79f7"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_45e152b5-c591-4bc6-a660-a7df9e952b85"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_dd771727-31c9-4522-b0e6-05546f4cd765"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_4ef2a7db-fd8c-4313-9a7d-e5c9b1fd7f0c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8014c048-5fca-4401-a2bd-b177742b0c6f"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a990b5b7-6fdb-4672-b666-87233955f2f1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_591ca979-be48-4507-a75a-5d7cfc656b97"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_fc4743ff-522b-46ca-830d-5d9b85ba3f67"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0a9dae54-cdc0-415e-8f57-1b5c7c131a84"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a8eacc01-2bb0-4ba5-9f05-7beba5b6a967"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3bfcc375-d6ae-4ce0-b3f7-54b6cab127a6"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_9607bcc8-6e79-45f8-afd8-2a3cbcdf084c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2befbf03-37c8-449c-b923-01fc4f7aca88"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8b2396bb-a34c-4e24-9678-ce52b8340571"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_b78bd5b3-12d1-4fa4-86f3-ffeb0cfa7c79"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_a8e42946-963b-41a6-a236-5ea5c2b94f08"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_40292fdf-7278-424a-85ef-29e21cb6f70b"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bfd831a2-12ac-499d-83de-3f7578249277"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bdff505b-1a8e-435a-bacd-442f3acde0ef"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f67a4a3d-d793-4909-85bc-3b4a9e501e47"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f8a82eb1-a0c8-4884-ad53-39ecacf6fe8c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_bb970ef7-7b27-4b3b-ab8f-288714e99eab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_86b75c42-81d6-4648-9777-c3a38ae380bd"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f149fc64-00c4-4859-9635-7274bec58fa3"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3c764176-339d-409b-875e-5d1256d6acf0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_3b3f47f5-a640-4568-bf83-cfdaf5892d0e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_cedbf97d-6183-4854-808e-51c89a3bc8d1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_466cad95-ed93-49e2-9b52-b7e519a1c220"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_efd00e1f-933b-4838-a75b-7488ebd5e114"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_680b6111-e389-4a42-874e-fb0aa6adbf8e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_482cb9b5-f418-4878-b55e-cdaafbfebbca"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1cf247dc-eff9-4d87-9e61-e18751909dd1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d081beac-642e-45bb-b35e-89d9027ead20"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_2276f5b4-9849-40cb-9201-defbf981db14"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_627a5e40-f5d9-46d3-947d-961d21bc057c"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8e2aa6f3-4fef-4229-a7e4-02fc5b9fef7a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0e48ab2d-78ad-4865-859e-57f4f308057e"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_d40bd31f-ca40-4c62-8209-027a25898685"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_66fc9dc5-0478-4558-994a-a14ef9218b98"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8806de92-0bb6-4c65-b0f3-14a062d41fdb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_6697b93a-c768-44cc-a568-547e37c39193"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_0f7e66bd-5118-4b8e-be33-f240a0a9d673"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_f8e864ea-509f-4ad0-a06a-92e347a26937"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_78c24bf0-8cc7-4bd5-8d67-68c6b0bc290a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_379198c7-8022-464c-a6f6-c3d6f446faf0"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_29be97ee-3f02-4655-8ead-df1bcec532c1"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_10c36b9c-753e-4620-9a1c-52f77292612a"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_486cbcb1-4d04-45de-b510-45284e584087"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8f573b22-2d80-47a7-8083-9fb6db102527"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_5635efe0-9b0c-4caf-a2d4-f1cd3081e2ab"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_1334299a-33fb-44dc-a219-486e760f8d93"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_8e61f56d-3789-4f02-84c1-97ea9ee6a540"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_235871ad-0dd6-4758-875f-bcdf6bf56012"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_09c9897e-315a-4907-abca-8fcff02610cb"></gml:surfaceMember>
									<gml:surfaceMember xlink:href="#ID_668ce416-2283-4e0d-a8ac-c7f919b6b2e8"></gml:surfaceMember>
								</gml:CompositeSurface>
							</gml:exterior>
						</gml:Solid>
					</bldg:lod2Solid>
					<bldg:boundedBy>
						<bldg:RoofSurface gml:id="ID_9aad33ee-12e4-4cfc-b9ca-9113b2190a2a">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_033d6b47-eb4e-42bf-a12e-6a7e9cb788bd">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cc08403d-b074-4691-a49e-c763be3d2564">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_162f7ab9-2d85-42a9-9497-a14ffe990ed5">
													<gml:posList>35.259643832141876 139.7385863904485 14.007 35.25965266456154 139.73850532836764 14.007 35.25961584798869 139.73855825537126 14.007 35.259643832141876 139.7385863904485 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_29cafac6-8b5a-459b-8f1d-143d60949d1e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_21e5f8f8-4ad8-4f81-abcf-a364f57d09e8">
													<gml:posList>35.25965266456154 139.73850532836764 14.007 35.25968399904368 139.73836336169092 14.007 35.25965168052363 139.73840982251252 14.007 35.25965266456154 139.73850532836764 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9c7d1bc6-541a-4e94-9da7-cab97dbc7dcc">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_30bffa51-cc11-457e-8729-f580d5d3e1b8">
													<gml:posList>35.25960453960058 139.73864287676795 14.007 35.25961584798869 139.73855825537126 14.007 35.25957574100256 139.7385167855726 14.007 35.25960453960058 139.73864287676795 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_50d3136b-ab09-4c96-a8cc-d54760caded2">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_37afb8ee-6bd5-49e7-b9c0-e5ab38d71534">
													<gml:posList>35.25943134072267 139.73872437273238 14.007 35.25960453960058 139.73864287676795 14.007 35.25957574100256 139.7385167855726 14.007 35.25943134072267 139.73872437273238 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ac9d4217-7092-4136-8d78-16ed1f4e7b90">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_466c3bf3-ad41-4291-a0c8-13c705520423">
													<gml:posList>35.25949829489728 139.7382526779176 14.007 35.259275491687816 139.7380223064613 14.007 35.2592378493168 139.73807642089898 14.007 35.25949829489728 139.7382526779176 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_dd4394c1-5030-43f3-838a-7ffed6f0db44">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3b002ce8-067a-4002-99eb-e2240f45c131">
													<gml:posList>35.25947144763866 139.7387658425601 14.007 35.25960453960058 139.73864287676795 14.007 35.25943134072267 139.73872437273238 14.007 35.25947144763866 139.7387658425601 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_7554e790-b6d3-4c3e-847c-270c96bce7d8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e1e13b93-cc47-41a0-b552-2167adcc8017">
													<gml:posList>35.25953315941118 139.7382872745984 14.007 35.25949829489728 139.7382526779176 14.007 35.2592378493168 139.73807642089898 14.007 35.25953315941118 139.7382872745984 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1ae4cd69-4b5e-405c-bd76-120f7ee9a3f1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b6b5322c-cdc1-43e9-b957-af3708c13a10">
													<gml:posList>35.259499108064276 139.7387944429737 14.007 35.25960453960058 139.73864287676795 14.007 35.25947144763866 139.7387658425601 14.007 35.259499108064276 139.7387944429737 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_490e9398-0d6d-4ef7-aada-90e65473c2aa">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e3cc0b99-ff04-4739-8c9a-c28b83bce04b">
													<gml:posList>35.25953315941118 139.7382872745984 14.007 35.25956536447386 139.73824097683504 14.007 35.25953108754047 139.73820553543945 14.007 35.25949829489728 139.7382526779176 14.007 35.25953315941118 139.7382872745984 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_ab78d717-15dc-43b3-9355-477fb04845f7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5d269012-a705-455e-ab38-ad8583674552">
													<gml:posList>35.25960453960058 139.73864287676795 14.007 35.259643832141876 139.7385863904485 14.007 35.25961584798869 139.73855825537126 14.007 35.25960453960058 139.73864287676795 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_346fb2ee-40f3-41b6-a0e5-55e7d760f25a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_a9eb58ec-67f2-44c6-b990-4e5c6b198044">
													<gml:posList>35.25964460292807 139.73868339346177 14.007 35.259643832141876 139.7385863904485 14.007 35.25960453960058 139.73864287676795 14.007 35.25964460292807 139.73868339346177 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6dd690a9-388d-43bd-8b69-d51e03d7d250">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_88f52ddd-6e41-4461-a46c-58ede4c8b4f8">
													<gml:posList>35.25968990008716 139.73872959874808 14.007 35.259643832141876 139.7385863904485 14.007 35.25964460292807 139.73868339346177 14.007 35.25968990008716 139.73872959874808 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_c5d91124-7a19-43f7-b333-4304a0cc79f7">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_39083fda-e016-4205-93b4-0aa4db3fc419">
													<gml:posList>35.25970337985148 139.73874334877107 14.007 35.259643832141876 139.7385863904485 14.007 35.25968990008716 139.73872959874808 14.007 35.25970337985148 139.73874334877107 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_45e152b5-c591-4bc6-a660-a7df9e952b85">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6a597f7f-e001-42c9-80f4-ee78f8793fcb">
													<gml:posList>35.25984920694045 139.73889373068548 14.007 35.25988764397698 139.7388384883027 14.007 35.25970337985148 139.73874334877107 14.007 35.25984920694045 139.73889373068548 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_dd771727-31c9-4522-b0e6-05546f4cd765">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_52a63b66-5eca-43ff-a66e-b5902e0d13de">
													<gml:posList>35.259643832141876 139.7385863904485 14.007 35.25968399904368 139.73836336169092 14.007 35.25965266456154 139.73850532836764 14.007 35.259643832141876 139.7385863904485 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_4ef2a7db-fd8c-4313-9a7d-e5c9b1fd7f0c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_16486778-1961-42be-bbd4-cd3653e2f167">
													<gml:posList>35.25988764397698 139.7388384883027 14.007 35.259643832141876 139.7385863904485 14.007 35.25970337985148 139.73874334877107 14.007 35.25988764397698 139.7388384883027 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8014c048-5fca-4401-a2bd-b177742b0c6f">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_98420203-ab03-4331-83ba-0fc128ee47c8">
													<gml:posList>35.25965168052363 139.73840982251252 14.007 35.25953315941118 139.7382872745984 14.007 35.2592378493168 139.73807642089898 14.007 35.25965168052363 139.73840982251252 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a990b5b7-6fdb-4672-b666-87233955f2f1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_035f151a-ca43-45bd-ab23-d42e6bbeda08">
													<gml:posList>35.25995567900424 139.73797199382997 14.007 35.2600937445063 139.73793959711526 14.007 35.26002596206708 139.7378695119702 14.007 35.25995567900424 139.73797199382997 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_591ca979-be48-4507-a75a-5d7cfc656b97">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3e69a3dc-dc5b-44fb-b977-7e8d8d8626e9">
													<gml:posList>35.259643832141876 139.7385863904485 14.007 35.2600937445063 139.73793959711526 14.007 35.25995567900424 139.73797199382997 14.007 35.259643832141876 139.7385863904485 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_fc4743ff-522b-46ca-830d-5d9b85ba3f67">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_91c73a55-9f5b-4ed8-bed4-600141cb5b4d">
													<gml:posList>35.259643832141876 139.7385863904485 14.007 35.25995567900424 139.73797199382997 14.007 35.25968399904368 139.73836336169092 14.007 35.259643832141876 139.7385863904485 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0a9dae54-cdc0-415e-8f57-1b5c7c131a84">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d37f322f-b65b-4a00-8494-983abc865d8f">
													<gml:posList>35.25965266456154 139.73850532836764 14.007 35.25965168052363 139.73840982251252 14.007 35.2592378493168 139.73807642089898 14.007 35.25965266456154 139.73850532836764 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a8eacc01-2bb0-4ba5-9f05-7beba5b6a967">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_27db7c92-a339-46cf-a319-0f6937788ec5">
													<gml:posList>35.25965208476815 139.73878470400086 16.39905526226481 35.25968990008716 139.73872959874808 16.39905526226481 35.25964460292807 139.73868339346177 16.39905526226481 35.25960678762981 139.73873849870526 16.39905526226481 35.25965208476815 139.73878470400086 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3bfcc375-d6ae-4ce0-b3f7-54b6cab127a6">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1ebd58b2-e977-42d7-ad2b-3d929ce98a90">
													<gml:posList>35.25969120476982 139.73876109055558 12.651 35.25970337985148 139.73874334877107 12.651 35.25968990008716 139.73872959874808 12.651 35.25967772500748 139.7387473405317 12.651 35.25969120476982 139.73876109055558 12.651</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:RoofSurface>
					</bldg:boundedBy>
					<bldg:boundedBy>
						<bldg:GroundSurface gml:id="ID_680d724c-e8b2-4157-a991-c6b66e4a3c9d">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_4b648e9c-e013-4769-902f-ca9f20849da4">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_9607bcc8-6e79-45f8-afd8-2a3cbcdf084c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d4a54560-c30e-40b4-b5f0-83bad1ece82d">
													<gml:posList>35.25957574100256 139.7385167855726 6.693040636924465 35.25961584798869 139.73855825537126 6.693040636924465 35.25965266456154 139.73850532836764 6.693040636924465 35.2592378493168 139.73807642089898 6.693040636924465 35.259275491687816 139.7380223064613 6.693040636924465 35.25949829489728 139.7382526779176 6.693040636924465 35.259514691221206 139.73822910668326 6.693040636924466 35.25953108754047 139.73820553543945 6.693040636924465 35.259548226008484 139.73822325613352 6.693040636924465 35.25956536447386 139.73824097683504 6.693040636924465 35.25953315941118 139.7382872745984 6.693040636924465 35.25965168052363 139.73840982251252 6.693040636924465 35.25968399904368 139.73836336169092 6.693040636924465 35.25981983918423 139.73816767808688 6.693040636924465 35.25995567900424 139.73797199382997 6.693040636924465 35.259990820546655 139.73792075292218 6.693040636924465 35.26002596206708 139.7378695119702 6.693040636924465 35.2600937445063 139.73793959711526 6.693040636924465 35.259643832141876 139.7385863904485 6.693040636924465 35.25988764397698 139.7388384883027 6.693040636924465 35.25984920694045 139.73889373068548 6.693040636924465 35.25970337985148 139.73874334877107 6.693040636924465 35.25969120476982 139.73876109055558 6.693040636924465 35.25967772500748 139.7387473405317 6.693040636924465 35.25965208476815 139.73878470400086 6.693040636924465 35.25960678762981 139.73873849870526 6.693040636924465 35.25964460292807 139.73868339346177 6.693040636924465 35.25960453960058 139.73864287676795 6.693040636924465 35.259499108064276 139.7387944429737 6.693040636924465 35.25947144763866 139.7387658425601 6.693040636924465 35.25943134072267 139.73872437273238 6.693040636924465 35.25957574100256 139.7385167855726 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:GroundSurface>
					</bldg:boundedBy>
					<bldg:boundedBy>
						<bldg:WallSurface gml:id="ID_a8fc6991-35fb-4fae-861c-f3903f9f8efa">
							<bldg:lod2MultiSurface>
								<gml:MultiSurface gml:id="ID_5d68482d-e0dc-4f1a-852e-d76dcaa4276b">
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2befbf03-37c8-449c-b923-01fc4f7aca88">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c92e1e1b-d2e0-4b50-8726-155f37355755">
													<gml:posList>35.25943134072267 139.73872437273238 14.007 35.25957574100256 139.7385167855726 14.007 35.25957574100256 139.7385167855726 6.693040636924465 35.25943134072267 139.73872437273238 6.693040636924465 35.25943134072267 139.73872437273238 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8b2396bb-a34c-4e24-9678-ce52b8340571">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fece9365-bdf4-453e-95e8-aeb6da57d63e">
													<gml:posList>35.25947144763866 139.7387658425601 14.007 35.25943134072267 139.73872437273238 14.007 35.25943134072267 139.73872437273238 6.693040636924465 35.25947144763866 139.7387658425601 6.693040636924465 35.25947144763866 139.7387658425601 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_b78bd5b3-12d1-4fa4-86f3-ffeb0cfa7c79">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9ba629e9-212c-4855-a60a-04072449817b">
													<gml:posList>35.259499108064276 139.7387944429737 14.007 35.25947144763866 139.7387658425601 14.007 35.25947144763866 139.7387658425601 6.693040636924465 35.259499108064276 139.7387944429737 6.693040636924465 35.259499108064276 139.7387944429737 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_a8e42946-963b-41a6-a236-5ea5c2b94f08">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7ca083be-421a-433d-b7e9-d418f693c4b3">
													<gml:posList>35.259499108064276 139.7387944429737 6.693040636924465 35.25960453960058 139.73864287676795 6.693040636924465 35.25960453960058 139.73864287676795 14.007 35.259499108064276 139.7387944429737 14.007 35.259499108064276 139.7387944429737 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_40292fdf-7278-424a-85ef-29e21cb6f70b">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_7c5432e4-8b3c-454f-a4d3-f9745d7af7e6">
													<gml:posList>35.25964460292807 139.73868339346177 14.007 35.25960453960058 139.73864287676795 14.007 35.25960453960058 139.73864287676795 6.693040636924465 35.25964460292807 139.73868339346177 6.693040636924465 35.25964460292807 139.73868339346177 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bfd831a2-12ac-499d-83de-3f7578249277">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_6dd343c5-7aea-4063-9f24-c358b8fb3135">
													<gml:posList>35.25970337985148 139.73874334877107 14.007 35.25968990008716 139.73872959874808 14.007 35.25968990008716 139.73872959874808 12.651 35.25970337985148 139.73874334877107 12.651 35.25970337985148 139.73874334877107 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bdff505b-1a8e-435a-bacd-442f3acde0ef">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4c87b458-da81-4f78-b7f4-dcc0cae03c03">
													<gml:posList>35.25984920694045 139.73889373068548 14.007 35.25970337985148 139.73874334877107 12.651 35.25970337985148 139.73874334877107 6.693040636924465 35.25984920694045 139.73889373068548 6.693040636924465 35.25984920694045 139.73889373068548 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f67a4a3d-d793-4909-85bc-3b4a9e501e47">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e13a2d82-1d6a-44d6-9cc1-3634a6d5f4ca">
													<gml:posList>35.25984920694045 139.73889373068548 14.007 35.25970337985148 139.73874334877107 14.007 35.25970337985148 139.73874334877107 12.651 35.25984920694045 139.73889373068548 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f8a82eb1-a0c8-4884-ad53-39ecacf6fe8c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_beb1e0e7-a1a3-4f3e-a21f-4fc3af99bec6">
													<gml:posList>35.25984920694045 139.73889373068548 6.693040636924465 35.25988764397698 139.7388384883027 6.693040636924465 35.25988764397698 139.7388384883027 14.007 35.25984920694045 139.73889373068548 14.007 35.25984920694045 139.73889373068548 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_bb970ef7-7b27-4b3b-ab8f-288714e99eab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d7bc2c79-5533-4e58-b964-dc70e51d4c4d">
													<gml:posList>35.25988764397698 139.7388384883027 6.693040636924465 35.259643832141876 139.7385863904485 6.693040636924465 35.259643832141876 139.7385863904485 14.007 35.25988764397698 139.7388384883027 14.007 35.25988764397698 139.7388384883027 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_86b75c42-81d6-4648-9777-c3a38ae380bd">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_4602eb02-b604-4c65-8ab3-5e88e4143bff">
													<gml:posList>35.259643832141876 139.7385863904485 6.693040636924465 35.2600937445063 139.73793959711526 6.693040636924465 35.2600937445063 139.73793959711526 14.007 35.259643832141876 139.7385863904485 14.007 35.259643832141876 139.7385863904485 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f149fc64-00c4-4859-9635-7274bec58fa3">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ea54d58f-4df7-4180-a4f0-854a87499528">
													<gml:posList>35.2600937445063 139.73793959711526 6.693040636924465 35.26002596206708 139.7378695119702 6.693040636924465 35.26002596206708 139.7378695119702 14.007 35.2600937445063 139.73793959711526 14.007 35.2600937445063 139.73793959711526 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3c764176-339d-409b-875e-5d1256d6acf0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_308167a6-f5b0-40fd-97c8-de1c0742bbc8">
													<gml:posList>35.25995567900424 139.73797199382997 14.007 35.259990820546655 139.73792075292218 6.693040636924465 35.25995567900424 139.73797199382997 6.693040636924465 35.25995567900424 139.73797199382997 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_3b3f47f5-a640-4568-bf83-cfdaf5892d0e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5f86cded-4fcd-4fc3-9115-b62ba36f5cee">
													<gml:posList>35.259990820546655 139.73792075292218 6.693040636924465 35.26002596206708 139.7378695119702 14.007 35.26002596206708 139.7378695119702 6.693040636924465 35.259990820546655 139.73792075292218 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_cedbf97d-6183-4854-808e-51c89a3bc8d1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8e722146-162e-482d-9101-2371028f0eeb">
													<gml:posList>35.25995567900424 139.73797199382997 14.007 35.26002596206708 139.7378695119702 14.007 35.259990820546655 139.73792075292218 6.693040636924465 35.25995567900424 139.73797199382997 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_466cad95-ed93-49e2-9b52-b7e519a1c220">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ada9deca-fbc0-4f55-9d7c-7708ed790c6f">
													<gml:posList>35.25968399904368 139.73836336169092 14.007 35.25981983918423 139.73816767808688 6.693040636924465 35.25968399904368 139.73836336169092 6.693040636924465 35.25968399904368 139.73836336169092 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_efd00e1f-933b-4838-a75b-7488ebd5e114">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3a8a97ea-4b77-425d-b0e3-07f63c584a91">
													<gml:posList>35.25981983918423 139.73816767808688 6.693040636924465 35.25995567900424 139.73797199382997 14.007 35.25995567900424 139.73797199382997 6.693040636924465 35.25981983918423 139.73816767808688 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_680b6111-e389-4a42-874e-fb0aa6adbf8e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5eacb90e-3933-4b31-8cfd-02c8067fbb8e">
													<gml:posList>35.25968399904368 139.73836336169092 14.007 35.25995567900424 139.73797199382997 14.007 35.25981983918423 139.73816767808688 6.693040636924465 35.25968399904368 139.73836336169092 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_482cb9b5-f418-4878-b55e-cdaafbfebbca">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_848306cd-3f9b-463b-8059-db21add02b0a">
													<gml:posList>35.25965168052363 139.73840982251252 14.007 35.25968399904368 139.73836336169092 14.007 35.25968399904368 139.73836336169092 6.693040636924465 35.25965168052363 139.73840982251252 6.693040636924465 35.25965168052363 139.73840982251252 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1cf247dc-eff9-4d87-9e61-e18751909dd1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5e91ffed-69fa-478e-b650-8d99b3944079">
													<gml:posList>35.25965168052363 139.73840982251252 6.693040636924465 35.25953315941118 139.7382872745984 6.693040636924465 35.25953315941118 139.7382872745984 14.007 35.25965168052363 139.73840982251252 14.007 35.25965168052363 139.73840982251252 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d081beac-642e-45bb-b35e-89d9027ead20">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_8f1d1753-5e03-43c9-9537-f9a3bf6f3ebd">
													<gml:posList>35.25953315941118 139.7382872745984 6.693040636924465 35.25956536447386 139.73824097683504 6.693040636924465 35.25956536447386 139.73824097683504 14.007 35.25953315941118 139.7382872745984 14.007 35.25953315941118 139.7382872745984 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_2276f5b4-9849-40cb-9201-defbf981db14">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_db8c7a0b-96ce-44c9-aeda-883256218ded">
													<gml:posList>35.259548226008484 139.73822325613352 6.693040636924465 35.25953108754047 139.73820553543945 6.693040636924465 35.25953108754047 139.73820553543945 14.007 35.259548226008484 139.73822325613352 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_627a5e40-f5d9-46d3-947d-961d21bc057c">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e625803b-d4c6-4349-a17c-67e3aa18521c">
													<gml:posList>35.25956536447386 139.73824097683504 14.007 35.25956536447386 139.73824097683504 6.693040636924465 35.259548226008484 139.73822325613352 6.693040636924465 35.25956536447386 139.73824097683504 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8e2aa6f3-4fef-4229-a7e4-02fc5b9fef7a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cca522c5-a277-4e76-bd49-c7b1f6164fb8">
													<gml:posList>35.25956536447386 139.73824097683504 14.007 35.259548226008484 139.73822325613352 6.693040636924465 35.25953108754047 139.73820553543945 14.007 35.25956536447386 139.73824097683504 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0e48ab2d-78ad-4865-859e-57f4f308057e">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_e2bf750a-ff48-4e03-a866-8daf9a395802">
													<gml:posList>35.25949829489728 139.7382526779176 14.007 35.259514691221206 139.73822910668326 6.693040636924466 35.25949829489728 139.7382526779176 6.693040636924465 35.25949829489728 139.7382526779176 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_d40bd31f-ca40-4c62-8209-027a25898685">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_5ca7a158-dc84-43ee-9b75-d274b83faed5">
													<gml:posList>35.259514691221206 139.73822910668326 6.693040636924466 35.25953108754047 139.73820553543945 14.007 35.25953108754047 139.73820553543945 6.693040636924465 35.259514691221206 139.73822910668326 6.693040636924466</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_66fc9dc5-0478-4558-994a-a14ef9218b98">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_3dbb2d47-ed77-47fb-a78b-332bdd80ad03">
													<gml:posList>35.25949829489728 139.7382526779176 14.007 35.25953108754047 139.73820553543945 14.007 35.259514691221206 139.73822910668326 6.693040636924466 35.25949829489728 139.7382526779176 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8806de92-0bb6-4c65-b0f3-14a062d41fdb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ccda17b7-c4ab-4869-b0ca-682693ba6e3a">
													<gml:posList>35.25949829489728 139.7382526779176 6.693040636924465 35.259275491687816 139.7380223064613 6.693040636924465 35.259275491687816 139.7380223064613 14.007 35.25949829489728 139.7382526779176 14.007 35.25949829489728 139.7382526779176 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_6697b93a-c768-44cc-a568-547e37c39193">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_f79de3d3-d26b-4681-ad82-daf3f94a364f">
													<gml:posList>35.2592378493168 139.73807642089898 14.007 35.259275491687816 139.7380223064613 14.007 35.259275491687816 139.7380223064613 6.693040636924465 35.2592378493168 139.73807642089898 6.693040636924465 35.2592378493168 139.73807642089898 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_0f7e66bd-5118-4b8e-be33-f240a0a9d673">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_fef9a548-c866-4def-9048-c46387bb6fb5">
													<gml:posList>35.25965266456154 139.73850532836764 14.007 35.2592378493168 139.73807642089898 14.007 35.2592378493168 139.73807642089898 6.693040636924465 35.25965266456154 139.73850532836764 6.693040636924465 35.25965266456154 139.73850532836764 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_f8e864ea-509f-4ad0-a06a-92e347a26937">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_cc783adc-bb9a-4253-8ecd-83f205988475">
													<gml:posList>35.25961584798869 139.73855825537126 14.007 35.25965266456154 139.73850532836764 14.007 35.25965266456154 139.73850532836764 6.693040636924465 35.25961584798869 139.73855825537126 6.693040636924465 35.25961584798869 139.73855825537126 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_78c24bf0-8cc7-4bd5-8d67-68c6b0bc290a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_2411e308-de66-46d0-86d7-c0d65ddd9b62">
													<gml:posList>35.25961584798869 139.73855825537126 6.693040636924465 35.25957574100256 139.7385167855726 6.693040636924465 35.25957574100256 139.7385167855726 14.007 35.25961584798869 139.73855825537126 14.007 35.25961584798869 139.73855825537126 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_379198c7-8022-464c-a6f6-c3d6f446faf0">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_ee5693dd-5dd7-4adb-aa96-730e8145860e">
													<gml:posList>35.25967772500748 139.7387473405317 12.651 35.25968990008716 139.73872959874808 14.007 35.25968990008716 139.73872959874808 16.39905526226481 35.25967772500748 139.7387473405317 12.651</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_29be97ee-3f02-4655-8ead-df1bcec532c1">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_d41f073c-dab4-4aed-88fa-9e911a87537b">
													<gml:posList>35.25967772500748 139.7387473405317 12.651 35.25968990008716 139.73872959874808 12.651 35.25968990008716 139.73872959874808 14.007 35.25967772500748 139.7387473405317 12.651</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_10c36b9c-753e-4620-9a1c-52f77292612a">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_1ffeadad-5534-4b7b-8093-3c310f1c20a0">
													<gml:posList>35.25965208476815 139.73878470400086 16.39905526226481 35.25965208476815 139.73878470400086 6.693040636924465 35.25967772500748 139.7387473405317 12.651 35.25965208476815 139.73878470400086 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_486cbcb1-4d04-45de-b510-45284e584087">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_c33a0c94-88c7-4819-92c7-198b4e05ea30">
													<gml:posList>35.25965208476815 139.73878470400086 16.39905526226481 35.25967772500748 139.7387473405317 12.651 35.25968990008716 139.73872959874808 16.39905526226481 35.25965208476815 139.73878470400086 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8f573b22-2d80-47a7-8083-9fb6db102527">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b48fe3b3-b87d-44df-9f14-dbd9c1269f28">
													<gml:posList>35.25965208476815 139.73878470400086 6.693040636924465 35.25967772500748 139.7387473405317 6.693040636924465 35.25967772500748 139.7387473405317 12.651 35.25965208476815 139.73878470400086 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_5635efe0-9b0c-4caf-a2d4-f1cd3081e2ab">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_9545c3b9-7ae8-4900-b698-29de135e79db">
													<gml:posList>35.25960678762981 139.73873849870526 16.39905526226481 35.25964460292807 139.73868339346177 14.007 35.25964460292807 139.73868339346177 6.693040636924465 35.25960678762981 139.73873849870526 6.693040636924465 35.25960678762981 139.73873849870526 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_1334299a-33fb-44dc-a219-486e760f8d93">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_46409b62-df01-4411-b8d3-8d9031ae3756">
													<gml:posList>35.25960678762981 139.73873849870526 16.39905526226481 35.25964460292807 139.73868339346177 16.39905526226481 35.25964460292807 139.73868339346177 14.007 35.25960678762981 139.73873849870526 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_8e61f56d-3789-4f02-84c1-97ea9ee6a540">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_594d0ed1-e715-4f9c-b909-1735aad10d0d">
													<gml:posList>35.25965208476815 139.73878470400086 16.39905526226481 35.25960678762981 139.73873849870526 16.39905526226481 35.25960678762981 139.73873849870526 6.693040636924465 35.25965208476815 139.73878470400086 6.693040636924465 35.25965208476815 139.73878470400086 16.39905526226481</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_235871ad-0dd6-4758-875f-bcdf6bf56012">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b556c6dc-441d-4c0d-99d9-c3b0b37a7e85">
													<gml:posList>35.25969120476982 139.73876109055558 6.693040636924465 35.25970337985148 139.73874334877107 6.693040636924465 35.25970337985148 139.73874334877107 12.651 35.25969120476982 139.73876109055558 12.651 35.25969120476982 139.73876109055558 6.693040636924465</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_09c9897e-315a-4907-abca-8fcff02610cb">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_213284fd-530b-4240-b326-85c429a8b407">
													<gml:posList>35.25969120476982 139.73876109055558 12.651 35.25967772500748 139.7387473405317 12.651 35.25967772500748 139.7387473405317 6.693040636924465 35.25969120476982 139.73876109055558 6.693040636924465 35.25969120476982 139.73876109055558 12.651</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
									<gml:surfaceMember>
										<gml:Polygon gml:id="ID_668ce416-2283-4e0d-a8ac-c7f919b6b2e8">
											<gml:exterior>
												<gml:LinearRing gml:id="ID_b3f5a0eb-74f6-4c3a-bd37-224eb97a77bb">
													<gml:posList>35.25968990008716 139.73872959874808 14.007 35.25964460292807 139.73868339346177 14.007 35.25964460292807 139.73868339346177 16.39905526226481 35.25968990008716 139.73872959874808 16.39905526226481 35.25968990008716 139.73872959874808 14.007</gml:posList>
												</gml:LinearRing>
											</gml:exterior>
										</gml:Polygon>
									</gml:surfaceMember>
								</gml:MultiSurface>
							</bldg:lod2MultiSurface>
						</bldg:WallSurface>
					</bldg:boundedBy>
					<uro:buildingIDAttribute>
						<uro:BuildingIDAttribute>
							<uro:buildingID>14201-bldg-156842</uro:buildingID>
							<uro:partID>2</uro:partID>
							<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
							<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
						</uro:BuildingIDAttribute>
					</uro:buildingIDAttribute>
					<uro:buildingDetailAttribute>
						<uro:BuildingDetailAttribute>
							<uro:totalFloorArea uom="m2">1106.05</uro:totalFloorArea>
							<uro:buildingStructureType codeSpace="../../codelists/Building_BuildingStructureType.xml">610</uro:buildingStructureType>
							<uro:buildingStructureOrgType codeSpace="../../codelists/BuildingDetailAttribute_buildingStructureOrgType.xml">2</uro:buildingStructureOrgType>
							<uro:orgUsage2 codeSpace="../../codelists/BuildingDetailAttribute_orgUsage2.xml">134</uro:orgUsage2>
							<uro:surveyYear>2016</uro:surveyYear>
						</uro:BuildingDetailAttribute>
					</uro:buildingDetailAttribute>
					<uro:buildingDisasterRiskAttribute>
						<uro:BuildingLandSlideRiskAttribute>
							<uro:description codeSpace="../../codelists/BuildingLandSlideRiskAttribute_description.xml">1</uro:description>
							<uro:areaType codeSpace="../../codelists/BuildingLandSlideRiskAttribute_areaType.xml">1</uro:areaType>
						</uro:BuildingLandSlideRiskAttribute>
					</uro:buildingDisasterRiskAttribute>
					<uro:buildingDisasterRiskAttribute>
						<uro:BuildingLandSlideRiskAttribute>
							<uro:description codeSpace="../../codelists/BuildingLandSlideRiskAttribute_description.xml">1</uro:description>
							<uro:areaType codeSpace="../../codelists/BuildingLandSlideRiskAttribute_areaType.xml">1</uro:areaType>
						</uro:BuildingLandSlideRiskAttribute>
					</uro:buildingDisasterRiskAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">104</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key104.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">105</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key105.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">106</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key106.xml">2</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
			<uro:keyValuePairAttribute>
				<uro:KeyValuePairAttribute>
					<uro:key codeSpace="../../codelists/KeyValuePairAttribute_key.xml">107</uro:key>
					<uro:codeValue codeSpace="../../codelists/KeyValuePairAttribute_key107.xml">1</uro:codeValue>
				</uro:KeyValuePairAttribute>
			</uro:keyValuePairAttribute>
					<uro:buildingDataQualityAttribute>
						<uro:BuildingDataQualityAttribute>
							<uro:lod1HeightType codeSpace="../../codelists/BuildingDataQualityAttribute_lod1HeightType.xml">6</uro:lod1HeightType>
						</uro:BuildingDataQualityAttribute>
					</uro:buildingDataQualityAttribute>
				</bldg:BuildingPart>
			</bldg:consistsOfBuildingPart>
			<uro:buildingIDAttribute>
				<uro:BuildingIDAttribute>
					<uro:buildingID>14201-bldg-156842</uro:buildingID>
					<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
					<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
				</uro:BuildingIDAttribute>
			</uro:buildingIDAttribute>
		</bldg:Building>
	</core:cityObjectMember>
	<core:cityObjectMember>
		<bldg:Building gml:id="bldg_548239d3-ad86-4649-b6d0-b060ef510fba">
			<bldg:measuredHeight uom="m">3.2</bldg:measuredHeight>
			<bldg:lod0FootPrint>
				<gml:MultiSurface>
					<gml:surfaceMember>
						<gml:Polygon>
							<gml:exterior>
								<gml:LinearRing>
									<gml:posList>35.258693417248274 139.74039689416588 4.09777593613 35.25869389182795 139.74041984476142 4.09777593613 35.25873733995323 139.74041850932974 4.09777593613 35.258736865373294 139.74039555872196 4.09777593613 35.258693417248274 139.74039689416588 4.09777593613</gml:posList>
								</gml:LinearRing>
							</gml:exterior>
						</gml:Polygon>
					</gml:surfaceMember>
				</gml:MultiSurface>
			</bldg:lod0FootPrint>
			<bldg:lod1Solid>
				<gml:Solid>
					<gml:exterior>
						<gml:CompositeSurface>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.258693417248274 139.74039689416588 4.09777593613 35.258736865373294 139.74039555872196 4.09777593613 35.25873733995323 139.74041850932974 4.09777593613 35.25869389182795 139.74041984476142 4.09777593613 35.258693417248274 139.74039689416588 4.09777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.258693417248274 139.74039689416588 4.09777593613 35.25869389182795 139.74041984476142 4.09777593613 35.25869389182795 139.74041984476142 7.25777593613 35.258693417248274 139.74039689416588 7.25777593613 35.258693417248274 139.74039689416588 4.09777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25869389182795 139.74041984476142 4.09777593613 35.25873733995323 139.74041850932974 4.09777593613 35.25873733995323 139.74041850932974 7.25777593613 35.25869389182795 139.74041984476142 7.25777593613 35.25869389182795 139.74041984476142 4.09777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25873733995323 139.74041850932974 4.09777593613 35.258736865373294 139.74039555872196 4.09777593613 35.258736865373294 139.74039555872196 7.25777593613 35.25873733995323 139.74041850932974 7.25777593613 35.25873733995323 139.74041850932974 4.09777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.258736865373294 139.74039555872196 4.09777593613 35.258693417248274 139.74039689416588 4.09777593613 35.258693417248274 139.74039689416588 7.25777593613 35.258736865373294 139.74039555872196 7.25777593613 35.258736865373294 139.74039555872196 4.09777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.258693417248274 139.74039689416588 7.25777593613 35.25869389182795 139.74041984476142 7.25777593613 35.25873733995323 139.74041850932974 7.25777593613 35.258736865373294 139.74039555872196 7.25777593613 35.258693417248274 139.74039689416588 7.25777593613</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:CompositeSurface>
					</gml:exterior>
				</gml:Solid>
			</bldg:lod1Solid>
			<uro:buildingIDAttribute>
				<uro:BuildingIDAttribute>
					<uro:buildingID>14201-bldg-112006</uro:buildingID>
					<uro:branchID>1</uro:branchID>
					<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
					<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
				</uro:BuildingIDAttribute>
			</uro:buildingIDAttribute>
			<uro:buildingDetailAttribute>
				<uro:BuildingDetailAttribute>
					<uro:surveyYear>2016</uro:surveyYear>
				</uro:BuildingDetailAttribute>
			</uro:buildingDetailAttribute>
			<uro:buildingDisasterRiskAttribute>
				<uro:BuildingLandSlideRiskAttribute>
					<uro:description codeSpace="../../codelists/BuildingLandSlideRiskAttribute_description.xml">1</uro:description>
					<uro:areaType codeSpace="../../codelists/BuildingLandSlideRiskAttribute_areaType.xml">1</uro:areaType>
				</uro:BuildingLandSlideRiskAttribute>
			</uro:buildingDisasterRiskAttribute>
			<uro:buildingDataQualityAttribute>
				<uro:BuildingDataQualityAttribute>
					<uro:lod1HeightType codeSpace="../../codelists/BuildingDataQualityAttribute_lod1HeightType.xml">6</uro:lod1HeightType>
				</uro:BuildingDataQualityAttribute>
			</uro:buildingDataQualityAttribute>
		</bldg:Building>
	</core:cityObjectMember>
	<core:cityObjectMember>
		<bldg:Building gml:id="bldg_9a608010-3663-4283-a6e8-0a86028f0636">
			<bldg:measuredHeight uom="m">5.0</bldg:measuredHeight>
			<bldg:lod0FootPrint>
				<gml:MultiSurface>
					<gml:surfaceMember>
						<gml:Polygon>
							<gml:exterior>
								<gml:LinearRing>
									<gml:posList>35.25996943421684 139.73939428915426 3.19475388527 35.25998709292263 139.73941256926565 3.19475388527 35.260005523443986 139.73938610452785 3.19475388527 35.259987864734235 139.73936782441808 3.19475388527 35.25996943421684 139.73939428915426 3.19475388527</gml:posList>
								</gml:LinearRing>
							</gml:exterior>
						</gml:Polygon>
					</gml:surfaceMember>
				</gml:MultiSurface>
			</bldg:lod0FootPrint>
			<bldg:lod1Solid>
				<gml:Solid>
					<gml:exterior>
						<gml:CompositeSurface>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25996943421684 139.73939428915426 3.19475388527 35.259987864734235 139.73936782441808 3.19475388527 35.260005523443986 139.73938610452785 3.19475388527 35.25998709292263 139.73941256926565 3.19475388527 35.25996943421684 139.73939428915426 3.19475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25996943421684 139.73939428915426 3.19475388527 35.25998709292263 139.73941256926565 3.19475388527 35.25998709292263 139.73941256926565 8.15475388527 35.25996943421684 139.73939428915426 8.15475388527 35.25996943421684 139.73939428915426 3.19475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25998709292263 139.73941256926565 3.19475388527 35.260005523443986 139.73938610452785 3.19475388527 35.260005523443986 139.73938610452785 8.15475388527 35.25998709292263 139.73941256926565 8.15475388527 35.25998709292263 139.73941256926565 3.19475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.260005523443986 139.73938610452785 3.19475388527 35.259987864734235 139.73936782441808 3.19475388527 35.259987864734235 139.73936782441808 8.15475388527 35.260005523443986 139.73938610452785 8.15475388527 35.260005523443986 139.73938610452785 3.19475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.259987864734235 139.73936782441808 3.19475388527 35.25996943421684 139.73939428915426 3.19475388527 35.25996943421684 139.73939428915426 8.15475388527 35.259987864734235 139.73936782441808 8.15475388527 35.259987864734235 139.73936782441808 3.19475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
							<gml:surfaceMember>
								<gml:Polygon>
									<gml:exterior>
										<gml:LinearRing>
											<gml:posList>35.25996943421684 139.73939428915426 8.15475388527 35.25998709292263 139.73941256926565 8.15475388527 35.260005523443986 139.73938610452785 8.15475388527 35.259987864734235 139.73936782441808 8.15475388527 35.25996943421684 139.73939428915426 8.15475388527</gml:posList>
										</gml:LinearRing>
									</gml:exterior>
								</gml:Polygon>
							</gml:surfaceMember>
						</gml:CompositeSurface>
					</gml:exterior>
				</gml:Solid>
			</bldg:lod1Solid>
			<uro:buildingIDAttribute>
				<uro:BuildingIDAttribute>
					<uro:buildingID>14201-bldg-110561</uro:buildingID>
					<uro:branchID>1</uro:branchID>
					<uro:prefecture codeSpace="../../codelists/Common_localPublicAuthorities.xml">14</uro:prefecture>
					<uro:city codeSpace="../../codelists/Common_localPublicAuthorities.xml">14201</uro:city>
				</uro:BuildingIDAttribute>
			</uro:buildingIDAttribute>
			<uro:buildingDetailAttribute>
				<uro:BuildingDetailAttribute>
					<uro:surveyYear>2016</uro:surveyYear>
				</uro:BuildingDetailAttribute>
			</uro:buildingDetailAttribute>
			<uro:buildingDisasterRiskAttribute>
				<uro:BuildingTsunamiRiskAttribute>
					<uro:description codeSpace="../../codelists/BuildingTsunamiRiskAttribute_description.xml">1</uro:description>
					<uro:rankOrg codeSpace="../../codelists/BuildingTsunamiRiskAttribute_rankOrg.xml">2</uro:rankOrg>
				</uro:BuildingTsunamiRiskAttribute>
			</uro:buildingDisasterRiskAttribute>
			<uro:buildingDataQualityAttribute>
				<uro:BuildingDataQualityAttribute>
					<uro:lod1HeightType codeSpace="../../codelists/BuildingDataQualityAttribute_lod1HeightType.xml">6</uro:lod1HeightType>
				</uro:BuildingDataQualityAttribute>
			</uro:buildingDataQualityAttribute>
		</bldg:Building>
	</core:cityObjectMember>
</core:CityModel>
