/*  The SPARQL conformance manifest of oro, in the spirit of the W3C
    SPARQL test manifests (written by us): one term a test,

        test(Name, DataFile, QueryFile, Expected).

    DataFile is a Turtle file of data/ loaded alone in a fresh store
    (oro_init([commonsense(false), ontologies([File])])), so the query
    sees the inference closure of that data, as find does; QueryFile is
    a query of queries/.  Expected is one of

      - rows(Vars, Rows)        SELECT: Vars the projected variables in
                                order, Rows the solutions as a bag
                                (order ignored, duplicates counted);
      - ordered(Vars, Rows)     the same, in this order (ORDER BY);
      - count(Vars, N)          N rows, whichever (LIMIT without ORDER BY);
      - ask(Bool)               ASK;
      - any_of(Expecteds)       one of these (order-dependent results);
      - syntax_error(Line, Col) the query is rejected with a syntax error
                                at that line and column (1-based).

    A row lists Var=Value for its bound variables.  Values are written
    briefly: an atom without a colon is a name in the default namespace
    (`kong` is <http://kb.openrobots.org#kong>), Prefix:Local a prefixed
    IRI, iri(Text) any IRI, `bnode` any blank node; a string is a simple
    literal, str(S) an xsd:string, lang(S, Tag) a language-tagged
    literal, int(N) an xsd:integer, dec(Lex) an xsd:decimal, dbl(Lex) an
    xsd:double, bool(B) an xsd:boolean and typed(Lex, Type) any typed
    literal.

    Queries and their expected results were written from the data by
    hand; every construct of issue 7 is covered.
*/

%   Basic graph patterns: abbreviations, blank nodes, collections, inference, IRIs, prefixes

test('bgp-01','zoo.ttl','bgp-01.rq',rows([x],[[x=kong],[x=lea],[x=mona]])).
test('bgp-02','zoo.ttl','bgp-02.rq',rows([x,w],[[x=kong,w=dec('180.5')],[x=lea,w=dec('40.0')],[x=mona,w=dec('52.25')]])).
test('bgp-03','zoo.ttl','bgp-03.rq',rows([x,n],[[x=lea,n="Lea"],[x=mona,n="Mona"]])).
test('bgp-04','zoo.ttl','bgp-04.rq',rows([x],[[x=lea]])).
test('bgp-05','zoo.ttl','bgp-05.rq',rows([x],[[x=kong],[x=lea],[x=mona],[x=rex],[x=tweety]])).
test('bgp-06','zoo.ttl','bgp-06.rq',rows([p],[[p=apple],[p=banana],[p=tree]])).
test('bgp-07','zoo.ttl','bgp-07.rq',rows([c,p],[[c=lea,p=mona]])).
test('bgp-08','zoo.ttl','bgp-08.rq',rows([o],[[o=branch],[o=tree]])).
test('bgp-09','zoo.ttl','bgp-09.rq',rows([s],[[s=branch],[s=tweety]])).
test('bgp-10','zoo.ttl','bgp-10.rq',rows([x],[[x=tweety]])).
test('bgp-11','zoo.ttl','bgp-11.rq',rows([x],[[x=tweety]])).
test('bgp-12','zoo.ttl','bgp-12.rq',rows([x],[[x=kong]])).
test('bgp-13','zoo.ttl','bgp-13.rq',rows([x],[[x=lea],[x=rex],[x=kong],[x=lea]])).
test('bgp-14','zoo.ttl','bgp-14.rq',rows([x],[[x=lea]])).
test('bgp-15','zoo.ttl','bgp-15.rq',rows([p],[[p=hasMother],[p=hasParent]])).
test('bgp-16','zoo.ttl','bgp-16.rq',rows([n],[[n="Kong"]])).
test('bgp-17','zoo.ttl','bgp-17.rq',rows([x],[[x=lea],[x=rex]])).
test('bgp-18','zoo.ttl','bgp-18.rq',rows([x],[[x=lea],[x=rex]])).
test('bgp-19','zoo.ttl','bgp-19.rq',rows([x],[[x=lea],[x=rex]])).
test('bgp-20','zoo.ttl','bgp-20.rq',rows([x],[])).
test('bgp-21','zoo.ttl','bgp-21.rq',rows([x,m,a],[[x=lea,m=mona,a=int(35)]])).
test('bgp-22','zoo.ttl','bgp-22.rq',rows([],[[]])).
test('bgp-23','zoo.ttl','bgp-23.rq',rows([x],[])).
test('bgp-24','paths.ttl','bgp-24.rq',rows([a,b],[[a=cup,b=plate]])).
test('bgp-25','zoo.ttl','bgp-25.rq',rows([x],[[x=kong],[x=lea]])).

%   FILTER: operators, scope, errors and three-valued logic, IN, EXISTS, regex

test('filter-01','zoo.ttl','filter-01.rq',rows([x],[[x=kong],[x=mona]])).
test('filter-02','zoo.ttl','filter-02.rq',rows([x],[[x=mona],[x=tweety]])).
test('filter-03','zoo.ttl','filter-03.rq',rows([x],[[x=kong]])).
test('filter-04','zoo.ttl','filter-04.rq',rows([x],[[x=tweety]])).
test('filter-05','zoo.ttl','filter-05.rq',rows([x],[[x=kong],[x=mona]])).
test('filter-06','zoo.ttl','filter-06.rq',rows([x],[])).
test('filter-07','zoo.ttl','filter-07.rq',rows([x],[[x=kong],[x=mona]])).
test('filter-08','zoo.ttl','filter-08.rq',rows([x],[])).
test('filter-09','zoo.ttl','filter-09.rq',rows([x],[[x=kong],[x=lea],[x=mona]])).
test('filter-10','zoo.ttl','filter-10.rq',rows([x],[[x=kong],[x=lea],[x=mona]])).
test('filter-11','zoo.ttl','filter-11.rq',rows([x],[[x=lea],[x=mona]])).
test('filter-12','zoo.ttl','filter-12.rq',rows([x],[[x=kong],[x=tweety]])).
test('filter-13','zoo.ttl','filter-13.rq',rows([x],[[x=lea],[x=rex]])).
test('filter-14','zoo.ttl','filter-14.rq',rows([x],[[x=mona]])).
test('filter-15','zoo.ttl','filter-15.rq',rows([x],[[x=mona],[x=rex],[x=tweety]])).
test('filter-16','zoo.ttl','filter-16.rq',rows([x],[[x=kong],[x=lea]])).
test('filter-17','zoo.ttl','filter-17.rq',rows([l],[[l=lang("kongo",fr)]])).
test('filter-18','zoo.ttl','filter-18.rq',rows([x],[[x=kong],[x=mona]])).
test('filter-19','zoo.ttl','filter-19.rq',rows([x],[[x=lea]])).
test('filter-20','zoo.ttl','filter-20.rq',rows([x],[[x=kong],[x=lea]])).

%   OPTIONAL

test('opt-01','zoo.ttl','opt-01.rq',rows([x,b],[[x=kong,b=typed("1990-05-01T00:00:00Z",xsd:dateTime)],[x=lea,b=typed("2008-02-10T12:00:00Z",xsd:dateTime)],[x=mona]])).
test('opt-02','zoo.ttl','opt-02.rq',rows([x,f],[[x=kong],[x=lea,f=apple],[x=mona],[x=rex,f=apple],[x=tweety]])).
test('opt-03','zoo.ttl','opt-03.rq',rows([x,a,w],[[x=kong,a=int(30),w=dec('180.5')],[x=lea,a=int(12),w=dec('40.0')],[x=mona,a=int(35),w=dec('52.25')],[x=rex,w=dec('30.0')],[x=tweety,a=typed("3",xsd:int)]])).
test('opt-04','zoo.ttl','opt-04.rq',rows([x,y],[[x=kong,y=mona],[x=lea],[x=mona],[x=tweety]])).

%   UNION and MINUS

test('union-01','zoo.ttl','union-01.rq',rows([x],[[x=tweety],[x=lea],[x=rex]])).
test('union-02','zoo.ttl','union-02.rq',rows([x,p],[[x=lea,p=mona],[p=branch],[p=tweety]])).
test('minus-01','zoo.ttl','minus-01.rq',rows([x],[[x=rex],[x=tweety]])).
test('minus-02','zoo.ttl','minus-02.rq',rows([x],[[x=tweety]])).

%   BIND, VALUES and SELECT expressions

test('bind-01','zoo.ttl','bind-01.rq',rows([x,b],[[x=kong,b=int(60)],[x=lea,b=int(24)],[x=mona,b=int(70)],[x=tweety,b=int(6)]])).
test('bind-02','zoo.ttl','bind-02.rq',rows([s],[[s="Lea of Mona"]])).
test('bind-03','zoo.ttl','bind-03.rq',rows([x,b],[[x=rex]])).
test('values-01','zoo.ttl','values-01.rq',rows([x,a],[[x=kong,a=int(30)],[x=rex]])).
test('values-02','zoo.ttl','values-02.rq',rows([x,n],[[x=kong,n="Kong"],[x=lea,n="Lea"]])).
test('values-03','zoo.ttl','values-03.rq',rows([x,w],[[x=lea,w=dec('40.0')],[x=mona,w=dec('52.25')]])).
test('project-01','zoo.ttl','project-01.rq',rows([x,b],[[x=lea,b=int(13)]])).
test('project-02','zoo.ttl','project-02.rq',rows([a,b],[[a=int(2),b=int(6)]])).

%   Solution modifiers: ORDER BY, LIMIT, OFFSET, DISTINCT, REDUCED

test('order-01','zoo.ttl','order-01.rq',ordered([x,a],[[x=tweety,a=typed("3",xsd:int)],[x=lea,a=int(12)],[x=kong,a=int(30)],[x=mona,a=int(35)]])).
test('order-02','zoo.ttl','order-02.rq',ordered([x],[[x=mona],[x=kong],[x=lea],[x=tweety]])).
test('order-03','zoo.ttl','order-03.rq',ordered([x],[[x=kong],[x=mona],[x=lea],[x=tweety]])).
test('order-04','zoo.ttl','order-04.rq',ordered([x,a],[[x=rex],[x=tweety,a=typed("3",xsd:int)],[x=lea,a=int(12)],[x=kong,a=int(30)],[x=mona,a=int(35)]])).
test('order-05','zoo.ttl','order-05.rq',ordered([n],[[n="Kong"],[n="Lea"],[n="Mona"],[n="Rex"],[n=str("Tweety")]])).
test('order-06','zoo.ttl','order-06.rq',ordered([x],[[x=kong],[x=mona],[x=lea],[x=rex]])).
test('limit-01','zoo.ttl','limit-01.rq',ordered([x],[[x=tweety],[x=lea]])).
test('limit-02','zoo.ttl','limit-02.rq',count([x],2)).
test('limit-03','zoo.ttl','limit-03.rq',rows([x],[])).
test('offset-01','zoo.ttl','offset-01.rq',ordered([x],[[x=lea],[x=kong]])).
test('offset-02','zoo.ttl','offset-02.rq',rows([x],[])).
test('distinct-01','zoo.ttl','distinct-01.rq',rows([x],[[x=kong],[x=lea],[x=rex]])).
test('distinct-02','zoo.ttl','distinct-02.rq',ordered([x],[[x=rex],[x=lea],[x=kong]])).
test('reduced-01','zoo.ttl','reduced-01.rq',rows([x],[[x=kong],[x=lea],[x=lea],[x=rex]])).

%   Aggregates and GROUP BY, HAVING

test('agg-01','zoo.ttl','agg-01.rq',rows([n],[[n=int(5)]])).
test('agg-02','zoo.ttl','agg-02.rq',rows([n],[[n=int(3)]])).
test('agg-03','zoo.ttl','agg-03.rq',rows([f,n],[[f=apple,n=int(2)],[f=banana,n=int(2)]])).
test('agg-04','zoo.ttl','agg-04.rq',rows([s,m],[[s=int(65),m=dec('32.5')]])).
test('agg-05','zoo.ttl','agg-05.rq',rows([lo,hi],[[lo=dec('30.0'),hi=dec('180.5')]])).
test('agg-06','zoo.ttl','agg-06.rq',rows([x],[[x=lea]])).
test('agg-07','zoo.ttl','agg-07.rq',any_of([rows([all],[[all="kong|kongo"]]),rows([all],[[all="kongo|kong"]])])).
test('agg-08','zoo.ttl','agg-08.rq',rows([s],[[s=int(12)]])).
test('agg-09','zoo.ttl','agg-09.rq',rows([n],[[n=int(0)]])).
test('agg-10','zoo.ttl','agg-10.rq',rows([old,n],[[old=bool(false),n=int(2)],[old=bool(true),n=int(2)]])).
test('agg-11','zoo.ttl','agg-11.rq',ordered([x,n],[[x=lea,n=int(2)],[x=kong,n=int(1)],[x=rex,n=int(1)]])).
test('agg-12','zoo.ttl','agg-12.rq',rows([m],[[m=int(0)]])).
test('agg-13','zoo.ttl','agg-13.rq',rows([s],[[]])).
test('agg-14','zoo.ttl','agg-14.rq',rows([n],[[n=int(4)]])).
test('agg-15','zoo.ttl','agg-15.rq',ordered([f,n,g],[[f=bool(false),n=int(1),g="false"],[f=bool(true),n=int(3),g="true"]])).

%   Property paths

test('path-01','paths.ttl','path-01.rq',rows([z],[[z=c]])).
test('path-02','paths.ttl','path-02.rq',rows([z],[[z=b],[z=c]])).
test('path-03','paths.ttl','path-03.rq',rows([z],[[z=a],[z=d]])).
test('path-04','paths.ttl','path-04.rq',rows([z],[[z=a],[z=b],[z=c],[z=d]])).
test('path-05','paths.ttl','path-05.rq',rows([z],[[z=b],[z=c],[z=d]])).
test('path-06','paths.ttl','path-06.rq',rows([z],[[z=a],[z=b]])).
test('path-07','paths.ttl','path-07.rq',rows([z],[[z=b],[z=c],[z=d]])).
test('path-08','paths.ttl','path-08.rq',ask(true)).
test('path-09','paths.ttl','path-09.rq',rows([z],[[z=a],[z=e]])).
test('path-10','paths.ttl','path-10.rq',rows([z],[[z=c]])).
test('path-11','paths.ttl','path-11.rq',rows([z],[[z=a]])).
test('path-12','paths.ttl','path-12.rq',rows([z],[[z=a]])).
test('path-13','paths.ttl','path-13.rq',rows([s,o],[[s=a,o=a],[s=x,o=x],[s=x,o=y],[s=y,o=y]])).
test('path-14','zoo.ttl','path-14.rq',rows([c],[[c='Animal'],[c=owl:'Thing'],[c='Bird']])).
test('path-15','paths.ttl','path-15.rq',rows([z],[[z=b],[z=c]])).
test('path-16','paths.ttl','path-16.rq',rows([z],[[z=b],[z=c],[z=d]])).
test('path-17','paths.ttl','path-17.rq',ask(true)).

%   Functions

test('fn-str','zoo.ttl','fn-str.rq',rows([s,t],[[s="http://kb.openrobots.org#kong",t="12"]])).
test('fn-lang','literals.ttl','fn-lang.rq',rows([v,l],[[v=lang("chat",fr),l="fr"],[v=lang("cat",'en-GB'),l="en-GB"]])).
test('fn-langmatches','literals.ttl','fn-langmatches.rq',rows([v],[[v=lang("cat",'en-GB')]])).
test('fn-langmatches-star','literals.ttl','fn-langmatches-star.rq',rows([v],[[v=lang("chat",fr)],[v=lang("cat",'en-GB')]])).
test('fn-datatype','literals.ttl','fn-datatype.rq',rows([x,d],[[x=i1,d=xsd:integer],[x=i2,d=xsd:int],[x=l1,d=rdf:langString],[x=s1,d=xsd:string],[x=u1,d=custom]])).
test('fn-isiri','literals.ttl','fn-isiri.rq',rows([x],[[x=r1]])).
test('fn-isuri','literals.ttl','fn-isuri.rq',rows([x],[[x=r1]])).
test('fn-isuri-terms','literals.ttl','fn-isuri-terms.rq',rows([a,b,c,d,e],[[a=bool(true),b=bool(false),c=bool(false),d=bool(false)]])).
test('fn-isblank','literals.ttl','fn-isblank.rq',rows([x],[[x=k1]])).
test('fn-isliteral','literals.ttl','fn-isliteral.rq',rows([n],[[n=int(17)]])).
test('fn-isnumeric','literals.ttl','fn-isnumeric.rq',rows([x],[[x=d1],[x=e1],[x=f1],[x=i1],[x=i2],[x=z1]])).
test('fn-strings-1','zoo.ttl','fn-strings-1.rq',rows([a,b,c,d,e,f,g],[[a=int(4),b="ABC",c=lang("abc",en),d="ab",e=lang("ab",en),f="ello",g="el"]])).
test('fn-strings-2','zoo.ttl','fn-strings-2.rq',rows([a,b,c,d,e,f],[[a=bool(true),b=bool(true),c=bool(true),d="a",e="b-c",f=""]])).
test('fn-incompatible','literals.ttl','fn-incompatible.rq',rows([r],[[]])).
test('fn-replace','literals.ttl','fn-replace.rq',rows([a,b,c],[[a="bANANa",b="xanana",c="a[b]c"]])).
test('fn-replace-group','literals.ttl','fn-replace-group.rq',rows([a,b,c,d],[[a="[1=ab][2=]cd",b="a\\b"]])).
test('fn-bnode-str','literals.ttl','fn-bnode-str.rq',rows([x,same,diff,blank],[[x="p",same=bool(true),diff=bool(false),blank=bool(true)]])).
test('fn-bnode-str-rows','literals.ttl','fn-bnode-str-rows.rq',rows([n],[[n=int(2)]])).
test('fn-cast-filter','literals.ttl','fn-cast-filter.rq',rows([x],[[x=b1],[x=b2],[x=d1],[x=i1],[x=i2],[x=z1],[x=f1],[x=e1]])).
test('fn-cast-datetime','literals.ttl','fn-cast-datetime.rq',rows([a,b,c,d,e],[[a=typed("2002-10-10T17:00:00Z",xsd:dateTime),b=typed("2002-10-10T17:00:00.5+02:00",xsd:dateTime),d=typed("2020-01-02T10:00:00Z",xsd:dateTime)]])).
test('fn-surrogate-pair','literals.ttl','fn-surrogate-pair.rq',rows([n,i],[[n=int(1),i="http://e/\u00e9"]])).
test('fn-cast-string','literals.ttl','fn-cast-string.rq',rows([a,b,c,d,e,f,g],[[a=str("1"),b=str("1"),c=str("false"),d=str("1.0E7"),e=str("2.5"),f=str("7"),g="1.0"]])).
test('fn-regex','literals.ttl','fn-regex.rq',rows([x],[[x=s2]])).
test('fn-regex-flags','literals.ttl','fn-regex-flags.rq',rows([a,b,c,d],[[a=bool(true),b=bool(false),c=bool(true),d=bool(true)]])).
test('fn-if-coalesce','literals.ttl','fn-if-coalesce.rq',rows([a,b,c],[[a="yes",c="c"]])).
test('fn-sameterm','literals.ttl','fn-sameterm.rq',rows([x],[[x=i1]])).
test('fn-numeric','literals.ttl','fn-numeric.rq',rows([a,b,c,d,e],[[a=int(3),b=dec('2.0'),c=dec('-2.0'),d=dec('3.0'),e=dec('-2.0')]])).
test('fn-casts','literals.ttl','fn-casts.rq',rows([a,b,c,d,e,f],[[a=int(42),b=dbl('1.0'),c=bool(true),d=str("3"),e=dec('1.5'),f=int(2)]])).
test('fn-cast-error','literals.ttl','fn-cast-error.rq',rows([a],[[]])).
test('fn-terms','literals.ttl','fn-terms.rq',rows([a,b,c,d],[[a=kong,b=typed("5",xsd:int),c=lang("chat",fr),d="a%20b%2F%C3%A9"]])).
test('fn-bound','zoo.ttl','fn-bound.rq',rows([x,has],[[x=kong,has=bool(true)],[x=lea,has=bool(true)],[x=mona,has=bool(false)]])).

%   Literal typing and the operator mapping

test('op-promote','literals.ttl','op-promote.rq',rows([a,b,c,d,e,f],[[a=int(3),b=dec('2.5'),c=dbl('2.0'),d=dec('3.5'),e=dec('2.0'),f=dec('5.0')]])).
test('op-float','literals.ttl','op-float.rq',rows([r],[[r=typed("3.5",xsd:float)]])).
test('op-subtract','literals.ttl','op-subtract.rq',rows([a,b,c,d,e,f,g,h],[[a=int(2),b=dec('-0.5'),c=dbl('2.0'),d=dec('2.0'),e=dec('-0.2'),f=int(3),g=int(3),h=int(2)]])).
test('op-subtract-typed','literals.ttl','op-subtract-typed.rq',rows([x,r],[[x=i1,r=int(0)],[x=i2,r=int(1)],[x=d1,r=dec('0.5')],[x=f1,r=typed("1.5",xsd:float)],[x=e1,r=dbl('9.0')],[x=z1,r=int(-1)],[x=s1],[x=s2],[x=s3],[x=l1],[x=l2],[x=b1],[x=b2],[x=x1],[x=u1],[x=t1],[x=t2],[x=r1],[x=k1]])).
test('op-subtract-vars','literals.ttl','op-subtract-vars.rq',rows([a,b,c,d],[[a=dbl('-9.0'),b=dec('-0.5'),c=typed("-1.5",xsd:float),d=dbl('-7.5')]])).
test('op-subtract-filter','literals.ttl','op-subtract-filter.rq',rows([x],[[x=d1],[x=i1],[x=z1]])).
test('op-numeric-eq','literals.ttl','op-numeric-eq.rq',rows([x],[[x=i1]])).
test('op-numeric-cmp','literals.ttl','op-numeric-cmp.rq',rows([x],[[x=d1],[x=f1],[x=i2]])).
test('op-not-equal','literals.ttl','op-not-equal.rq',rows([x],[[x=k1],[x=l1],[x=l2],[x=r1],[x=s2],[x=s3]])).
test('op-lang-eq','literals.ttl','op-lang-eq.rq',rows([x],[[x=l1]])).
test('op-boolean','literals.ttl','op-boolean.rq',rows([x],[[x=b2]])).
test('op-boolean-order','literals.ttl','op-boolean-order.rq',rows([x],[[x=b2]])).
test('op-datetime','literals.ttl','op-datetime.rq',rows([x],[[x=t2]])).
test('op-ill-typed','literals.ttl','op-ill-typed.rq',rows([x],[[x=x1]])).
test('op-custom','literals.ttl','op-custom.rq',rows([x],[[x=u1]])).
test('op-ebv','literals.ttl','op-ebv.rq',rows([x],[[x=b1],[x=d1],[x=e1],[x=f1],[x=i1],[x=i2],[x=s1],[x=s2]])).
test('op-unary','literals.ttl','op-unary.rq',rows([a,b,c],[[a=int(3),b=int(2),c=bool(true)]])).
test('op-string-order','literals.ttl','op-string-order.rq',rows([v],[[v="apple"],[v=str("Banana")],[v=""]])).
test('op-division-zero','literals.ttl','op-division-zero.rq',rows([r],[[]])).

%   ASK and sub-SELECT

test('ask-01','zoo.ttl','ask-01.rq',ask(true)).
test('ask-02','zoo.ttl','ask-02.rq',ask(false)).
test('ask-03','zoo.ttl','ask-03.rq',ask(false)).
test('sub-01','zoo.ttl','sub-01.rq',rows([x,n],[[x=kong,n=int(1)],[x=lea,n=int(2)]])).
test('sub-02','zoo.ttl','sub-02.rq',rows([x],[[x=mona]])).

%   Malformed queries: a syntax error at a line and column

test('bad-01','zoo.ttl','bad-01.rq',syntax_error(2,1)).
test('bad-02','zoo.ttl','bad-02.rq',syntax_error(1,24)).
test('bad-03','zoo.ttl','bad-03.rq',syntax_error(1,37)).
test('bad-21','zoo.ttl','bad-21.rq',syntax_error(1,28)).
test('bad-04','zoo.ttl','bad-04.rq',syntax_error(1,1)).
test('bad-05','zoo.ttl','bad-05.rq',syntax_error(1,28)).
test('bad-06','zoo.ttl','bad-06.rq',syntax_error(1,28)).
test('bad-07','zoo.ttl','bad-07.rq',syntax_error(4,15)).
test('bad-08','zoo.ttl','bad-08.rq',syntax_error(1,9)).
test('bad-09','zoo.ttl','bad-09.rq',syntax_error(1,37)).
test('bad-10','zoo.ttl','bad-10.rq',syntax_error(1,8)).
test('bad-11','zoo.ttl','bad-11.rq',syntax_error(1,32)).
test('bad-12','zoo.ttl','bad-12.rq',syntax_error(1,1)).
test('bad-13','zoo.ttl','bad-13.rq',syntax_error(1,8)).
test('bad-14','zoo.ttl','bad-14.rq',syntax_error(1,40)).
test('bad-15','zoo.ttl','bad-15.rq',syntax_error(1,30)).
test('bad-16','zoo.ttl','bad-16.rq',syntax_error(1,19)).
test('bad-17','zoo.ttl','bad-17.rq',syntax_error(1,35)).
test('bad-18','zoo.ttl','bad-18.rq',syntax_error(1,42)).
test('bad-19','zoo.ttl','bad-19.rq',syntax_error(1,16)).
test('bad-20','zoo.ttl','bad-20.rq',syntax_error(1,38)).
