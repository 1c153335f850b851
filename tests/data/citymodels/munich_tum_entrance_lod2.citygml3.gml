<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<CityModel xmlns:con="http://www.opengis.net/citygml/construction/3.0" xmlns:tran="http://www.opengis.net/citygml/transportation/3.0" xmlns:wtr="http://www.opengis.net/citygml/waterbody/3.0" xmlns:veg="http://www.opengis.net/citygml/vegetation/3.0" xmlns="http://www.opengis.net/citygml/3.0" xmlns:dem="http://www.opengis.net/citygml/relief/3.0" xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:bldg="http://www.opengis.net/citygml/building/3.0" xmlns:ct="urn:oasis:names:tc:ciq:ct:3" xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/3.0" xmlns:dyn="http://www.opengis.net/citygml/dynamizer/3.0" xmlns:pcl="http://www.opengis.net/citygml/pointcloud/3.0" xmlns:tun="http://www.opengis.net/citygml/tunnel/3.0" xmlns:frn="http://www.opengis.net/citygml/cityfurniture/3.0" xmlns:gen="http://www.opengis.net/citygml/generics/3.0" xmlns:xAL="urn:oasis:names:tc:ciq:xal:3" xmlns:app="http://www.opengis.net/citygml/appearance/3.0" xmlns:luse="http://www.opengis.net/citygml/landuse/3.0" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmlns:brid="http://www.opengis.net/citygml/bridge/3.0" xmlns:vers="http://www.opengis.net/citygml/versioning/3.0" xmlns:xlink="http://www.w3.org/1999/xlink" xsi:schemaLocation="http://www.opengis.net/citygml/construction/3.0 http://schemas.opengis.net/citygml/construction/3.0/construction.xsd http://www.opengis.net/citygml/transportation/3.0 http://schemas.opengis.net/citygml/transportation/3.0/transportation.xsd http://www.opengis.net/citygml/waterbody/3.0 http://schemas.opengis.net/citygml/waterbody/3.0/waterBody.xsd http://www.opengis.net/citygml/vegetation/3.0 http://schemas.opengis.net/citygml/vegetation/3.0/vegetation.xsd http://www.opengis.net/citygml/relief/3.0 http://schemas.opengis.net/citygml/relief/3.0/relief.xsd http://www.opengis.net/citygml/building/3.0 http://schemas.opengis.net/citygml/building/3.0/building.xsd http://www.opengis.net/citygml/cityobjectgroup/3.0 http://schemas.opengis.net/citygml/cityobjectgroup/3.0/cityObjectGroup.xsd http://www.opengis.net/citygml/dynamizer/3.0 http://schemas.opengis.net/citygml/dynamizer/3.0/dynamizer.xsd http://www.opengis.net/citygml/pointcloud/3.0 http://schemas.opengis.net/citygml/pointcloud/3.0/pointCloud.xsd http://www.opengis.net/citygml/tunnel/3.0 http://schemas.opengis.net/citygml/tunnel/3.0/tunnel.xsd http://www.opengis.net/citygml/cityfurniture/3.0 http://schemas.opengis.net/citygml/cityfurniture/3.0/cityFurniture.xsd http://www.opengis.net/citygml/generics/3.0 http://schemas.opengis.net/citygml/generics/3.0/generics.xsd http://www.opengis.net/citygml/appearance/3.0 http://schemas.opengis.net/citygml/appearance/3.0/appearance.xsd http://www.opengis.net/citygml/landuse/3.0 http://schemas.opengis.net/citygml/landuse/3.0/landUse.xsd http://www.opengis.net/citygml/bridge/3.0 http://schemas.opengis.net/citygml/bridge/3.0/bridge.xsd http://www.opengis.net/citygml/versioning/3.0 http://schemas.opengis.net/citygml/versioning/3.0/versioning.xsd">
  <gml:name>LoD2_32_690_5336_2_BY</gml:name>
  <gml:boundedBy>
    <gml:Envelope srsName="urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH" srsDimension="3">
      <gml:lowerCorner>689975.68 5335962.63 503.0</gml:lowerCorner>
      <gml:upperCorner>692025.893 5338012.713 581.62</gml:upperCorner>
    </gml:Envelope>
  </gml:boundedBy>
  <cityObjectMember>
    <bldg:Building gml:id="DEBY_LOD2_4959457">
      <creationDate>2025-01-02T00:00:00+01:00</creationDate>
      <externalReference>
        <ExternalReference>
          <targetResource>DEBYvAAAAABTMIyA</targetResource>
          <informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</informationSystem>
        </ExternalReference>
      </externalReference>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>DatenquelleBodenhoehe</gen:name>
          <gen:value>1100</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>DatenquelleDachhoehe</gen:name>
          <gen:value>1000</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>DatenquelleLage</gen:name>
          <gen:value>1000</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>Gemeindeschluessel</gen:name>
          <gen:value>09162000</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>HoeheDach</gen:name>
          <gen:value>534.450</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>HoeheGrund</gen:name>
          <gen:value>515.042</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>Methode</gen:name>
          <gen:value>2000</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>NiedrigsteTraufeDesGebaeudes</gen:name>
          <gen:value>527.312</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>Grundrissaktualitaet</gen:name>
          <gen:value>2025-02-17</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <genericAttribute>
        <gen:StringAttribute>
          <gen:name>Geometrietyp2DReferenz</gen:name>
          <gen:value>3000</gen:value>
        </gen:StringAttribute>
      </genericAttribute>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_ca1db42f-9d12-4f41-972c-c7da1614f0a8_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>546.695</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>-0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_ca1db42f-9d12-4f41-972c-c7da1614f0a8_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691043.75 5336009.96 515.042 691048.01 5336020.78 515.042 691054.07 5336036.17 515.042 691054.07 5336036.17 534.45 691048.01 5336020.78 534.45 691043.75 5336009.96 534.45 691043.75 5336009.96 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_239ebf3e-81f6-45a5-a3e4-581428bb8c0d_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>594.952</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_239ebf3e-81f6-45a5-a3e4-581428bb8c0d_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691025.55 5336047.41 515.042 691025.55 5336047.41 534.45 691054.07 5336036.17 534.45 691054.07 5336036.17 515.042 691025.55 5336047.41 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_96c347e9-9c46-4ee8-a4f0-ffb50dba3298_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>232.962</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_96c347e9-9c46-4ee8-a4f0-ffb50dba3298_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691021.13 5336036.25 515.042 691021.13 5336036.25 527.312 691021.13 5336036.25 534.45 691025.55 5336047.41 534.45 691025.55 5336047.41 515.042 691021.13 5336036.25 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_059be067-885f-4a1c-a46b-e188e0385304_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>321.082</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_059be067-885f-4a1c-a46b-e188e0385304_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691043.75 5336009.96 515.042 691043.75 5336009.96 534.45 691037.68 5335994.57 534.45 691037.68 5335994.57 515.042 691043.75 5336009.96 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_53eebcf5-3e5f-40ff-9cfd-c36f0e7312dd_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>146.189</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>12.268</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>527.310</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_53eebcf5-3e5f-40ff-9cfd-c36f0e7312dd_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691030.04 5336015.17 515.042 691030.04 5336015.17 527.31 691034.4 5336026.26 527.31 691034.4 5336026.26 515.042 691030.04 5336015.17 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_bbd99b7d-8f04-424a-9e7d-42594b4423a1_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>147.933</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>12.271</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>527.312</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_bbd99b7d-8f04-424a-9e7d-42594b4423a1_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691031.244 5336010.074 527.312 691031.244 5336010.074 534.45 691038.838 5336029.359 534.45 691038.838 5336029.359 527.312 691031.244 5336010.074 527.312</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_671f56d2-f0d8-4a45-a4ff-c74d19d39255_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>256.871</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>-0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_671f56d2-f0d8-4a45-a4ff-c74d19d39255_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691013.54 5336016.86 534.45 691013.61 5336017.038 534.45 691013.61 5336017.038 527.312 691015.013 5336020.624 527.312 691019.816 5336032.893 527.312 691021.13 5336036.25 527.312 691021.13 5336036.25 515.042 691019.816 5336032.893 515.042 691015.013 5336020.624 515.042 691013.61 5336017.038 515.042 691013.54 5336016.86 515.042 691013.54 5336016.86 534.45</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_d685fb5b-0534-4dfc-8dcd-13006e801d36_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>232.316</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_d685fb5b-0534-4dfc-8dcd-13006e801d36_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691009.16 5336005.72 515.042 691009.16 5336005.72 534.45 691013.54 5336016.86 534.45 691013.54 5336016.86 515.042 691009.16 5336005.72 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_d1d6b058-bc03-4329-a10d-27ac55b43ae8_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>594.314</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_d1d6b058-bc03-4329-a10d-27ac55b43ae8_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691037.68 5335994.57 515.042 691037.68 5335994.57 534.45 691009.16 5336005.72 534.45 691009.16 5336005.72 515.042 691037.68 5335994.57 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_be21ab59-0f31-4c5f-9763-2b1a4a8d4e99_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>135.624</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>12.271</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>527.312</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_be21ab59-0f31-4c5f-9763-2b1a4a8d4e99_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691038.838 5336029.359 527.312 691038.838 5336029.359 534.45 691021.13 5336036.25 534.45 691021.13 5336036.25 527.312 691038.838 5336029.359 527.312</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:GroundSurface gml:id="DEBY_LOD2_4959457_2470b16f-99f0-43c3-9a27-bd4fc3822c91_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>1229.560</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>-0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_2470b16f-99f0-43c3-9a27-bd4fc3822c91_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691048.01 5336020.78 515.042 691043.75 5336009.96 515.042 691037.68 5335994.57 515.042 691009.16 5336005.72 515.042 691013.54 5336016.86 515.042 691013.61 5336017.038 515.042 691015.013 5336020.624 515.042 691019.816 5336032.893 515.042 691021.13 5336036.25 515.042 691025.55 5336047.41 515.042 691054.07 5336036.17 515.042 691048.01 5336020.78 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList>691023.31 5336030.64 515.042 691018.94 5336019.52 515.042 691030.04 5336015.17 515.042 691034.4 5336026.26 515.042 691023.31 5336030.64 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:GroundSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_3a167af6-e0c6-47d4-9ee9-a003c3c15ed8_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>146.258</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>12.268</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>527.310</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_3a167af6-e0c6-47d4-9ee9-a003c3c15ed8_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691018.94 5336019.52 515.042 691018.94 5336019.52 527.31 691030.04 5336015.17 527.31 691030.04 5336015.17 515.042 691018.94 5336019.52 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_c68a57d8-91c5-4eb8-a7ef-6fe462db06ba_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>135.322</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>12.271</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>527.312</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_c68a57d8-91c5-4eb8-a7ef-6fe462db06ba_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691013.61 5336017.038 527.312 691013.61 5336017.038 534.45 691031.244 5336010.074 534.45 691031.244 5336010.074 527.312 691013.61 5336017.038 527.312</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_bd09fa02-b196-4143-87b9-93c9ede0f374_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>146.576</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>12.268</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>527.310</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_bd09fa02-b196-4143-87b9-93c9ede0f374_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691023.31 5336030.64 515.042 691023.31 5336030.64 527.31 691018.94 5336019.52 527.31 691018.94 5336019.52 515.042 691023.31 5336030.64 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <boundary>
        <con:RoofSurface gml:id="DEBY_LOD2_4959457_8ece9343-98c4-4165-8d23-892122af84a4_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Dachneigung</gen:name>
              <gen:value>90.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Dachorientierung</gen:name>
              <gen:value>-1.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>250.224</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>12.271</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>527.312</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>12.271</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>527.312</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_8ece9343-98c4-4165-8d23-892122af84a4_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691031.244 5336010.074 527.312 691038.838 5336029.359 527.312 691021.13 5336036.25 527.312 691019.816 5336032.893 527.312 691015.013 5336020.624 527.312 691013.61 5336017.038 527.312 691031.244 5336010.074 527.312</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                  <gml:interior>
                    <gml:LinearRing>
                      <gml:posList>691023.31 5336030.64 527.31 691034.4 5336026.26 527.31 691030.04 5336015.17 527.31 691018.94 5336019.52 527.31 691023.31 5336030.64 527.31</gml:posList>
                    </gml:LinearRing>
                  </gml:interior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:RoofSurface>
      </boundary>
      <boundary>
        <con:RoofSurface gml:id="DEBY_LOD2_4959457_6dbe45cf-414f-4333-8cd8-68b9075a3599_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Dachneigung</gen:name>
              <gen:value>90.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Dachorientierung</gen:name>
              <gen:value>-1.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>979.336</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>19.408</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>534.450</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_6dbe45cf-414f-4333-8cd8-68b9075a3599_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691037.68 5335994.57 534.45 691043.75 5336009.96 534.45 691048.01 5336020.78 534.45 691054.07 5336036.17 534.45 691025.55 5336047.41 534.45 691021.13 5336036.25 534.45 691038.838 5336029.359 534.45 691031.244 5336010.074 534.45 691013.61 5336017.038 534.45 691013.54 5336016.86 534.45 691009.16 5336005.72 534.45 691037.68 5335994.57 534.45</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:RoofSurface>
      </boundary>
      <boundary>
        <con:WallSurface gml:id="DEBY_LOD2_4959457_41005d74-6443-4772-a097-1ef1d0d22628_2">
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Flaeche</gen:name>
              <gen:value>146.279</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX</gen:name>
              <gen:value>12.268</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MAX_ASL</gen:name>
              <gen:value>527.310</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN</gen:name>
              <gen:value>0.000</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <genericAttribute>
            <gen:StringAttribute>
              <gen:name>Z_MIN_ASL</gen:name>
              <gen:value>515.042</gen:value>
            </gen:StringAttribute>
          </genericAttribute>
          <lod2MultiSurface>
            <gml:MultiSurface srsDimension="3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="DEBY_LOD2_4959457_41005d74-6443-4772-a097-1ef1d0d22628_2_poly">
                  <gml:exterior>
                    <gml:LinearRing>
                      <gml:posList>691034.4 5336026.26 515.042 691034.4 5336026.26 527.31 691023.31 5336030.64 527.31 691023.31 5336030.64 515.042 691034.4 5336026.26 515.042</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </lod2MultiSurface>
        </con:WallSurface>
      </boundary>
      <lod2Solid>
        <gml:Solid srsDimension="3">
          <gml:exterior>
            <gml:Shell>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_ca1db42f-9d12-4f41-972c-c7da1614f0a8_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_239ebf3e-81f6-45a5-a3e4-581428bb8c0d_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_96c347e9-9c46-4ee8-a4f0-ffb50dba3298_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_059be067-885f-4a1c-a46b-e188e0385304_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_53eebcf5-3e5f-40ff-9cfd-c36f0e7312dd_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_bbd99b7d-8f04-424a-9e7d-42594b4423a1_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_671f56d2-f0d8-4a45-a4ff-c74d19d39255_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_d685fb5b-0534-4dfc-8dcd-13006e801d36_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_d1d6b058-bc03-4329-a10d-27ac55b43ae8_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_be21ab59-0f31-4c5f-9763-2b1a4a8d4e99_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_2470b16f-99f0-43c3-9a27-bd4fc3822c91_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_3a167af6-e0c6-47d4-9ee9-a003c3c15ed8_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_c68a57d8-91c5-4eb8-a7ef-6fe462db06ba_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_bd09fa02-b196-4143-87b9-93c9ede0f374_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_8ece9343-98c4-4165-8d23-892122af84a4_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_6dbe45cf-414f-4333-8cd8-68b9075a3599_2_poly"/>
              <gml:surfaceMember xlink:href="#DEBY_LOD2_4959457_41005d74-6443-4772-a097-1ef1d0d22628_2_poly"/>
            </gml:Shell>
          </gml:exterior>
        </gml:Solid>
      </lod2Solid>
      <con:height>
        <con:Height>
          <con:highReference>highestRoofEdge</con:highReference>
          <con:lowReference>lowestGroundPoint</con:lowReference>
          <con:status>measured</con:status>
          <con:value uom="urn:adv:uom:m">19.408</con:value>
        </con:Height>
      </con:height>
      <bldg:function>31001_3020</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:storeysAboveGround>4</bldg:storeysAboveGround>
      <bldg:address>
        <Address>
          <xalAddress>
            <xAL:Address>
              <xAL:Country>
                <xAL:NameElement xAL:NameType="Name">Germany</xAL:NameElement>
              </xAL:Country>
              <xAL:Locality xAL:Type="Town">
                <xAL:NameElement xAL:NameType="Name">München</xAL:NameElement>
              </xAL:Locality>
              <xAL:Thoroughfare xAL:Type="Street">
                <xAL:NameElement>Arcisstraße 21</xAL:NameElement>
              </xAL:Thoroughfare>
            </xAL:Address>
          </xalAddress>
        </Address>
      </bldg:address>
    </bldg:Building>
  </cityObjectMember>
</CityModel>